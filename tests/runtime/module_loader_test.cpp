#include "runtime/module_loader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <stdlib.h>

#include <sstream>
#include <string>

#include "runtime/operator_registry.h"
#include "test_util.h"

namespace maquette {
namespace {

using test::error_of;
using test::fixture_dir;
using ::testing::HasSubstr;

TEST(ModuleLoader, SearchPathIsEnvironmentThenNextToTheProgram) {
  setenv("MAQUETTE_MODULE_PATH", "/a/b::/c", 1);
  const auto dirs = module_search_path();
  unsetenv("MAQUETTE_MODULE_PATH");
  ASSERT_EQ(dirs.size(), 3u);
  EXPECT_EQ(dirs[0], "/a/b");
  EXPECT_EQ(dirs[1], "/c");
  EXPECT_THAT(dirs[2], ::testing::EndsWith("/lib/maquette"));
}

TEST(ModuleLoader, FirstFileOfANameWins) {
  const auto files = find_module_files({fixture_dir("good"), fixture_dir("good"), "/nonexistent"});
  ASSERT_EQ(files.size(), 1u);
  EXPECT_EQ(files[0], fixture_dir("good") + "/libfixture_ops.so");
}

TEST(ModuleLoader, RefusesAnotherAbiNamingTheFile) {
  const std::string file = fixture_dir("bad_abi") + "/libfixture_bad_abi.so";
  const std::string expected = file + " was built for module ABI 1, this maquette has ABI " +
                               std::to_string(MAQUETTE_ABI_VERSION) + ": rebuild it";
  EXPECT_EQ(error_of([&] { load_module(file); }), expected);
  EXPECT_EQ(error_of([&] { OperatorRegistry::load({fixture_dir("bad_abi")}); }), expected);
}

TEST(ModuleLoader, RefusesALibraryWithoutEntryPoint) {
  const std::string file = fixture_dir("no_entry") + "/libfixture_no_entry.so";
  EXPECT_EQ(error_of([&] { load_module(file); }),
            file + " is not a Maquette module: no maquette_module_info entry point");
}

TEST(ModuleLoader, RefusesAFileThatIsNoLibrary) {
  EXPECT_THAT(error_of([] { load_module("/nonexistent/libx.so"); }),
              HasSubstr("cannot load module /nonexistent/libx.so"));
}

TEST(OperatorRegistry, RefusesAnOutputOfKindModelNamingFileAndPort) {
  const std::string file = fixture_dir("bad_port") + "/libfixture_bad_port.so";
  EXPECT_EQ(error_of([] { OperatorRegistry::load({fixture_dir("bad_port")}); }),
            file + ": operator 'fixture.writes_model': output 'prototype' writes model layers " +
                "(outputs write raster or 3D content layers)");
}

TEST(OperatorRegistry, RejectsDuplicateOperatorNamingBothFiles) {
  const std::string message = error_of([] {
    OperatorRegistry::load({fixture_dir("good"), fixture_dir("dup")});
  });
  EXPECT_THAT(message, HasSubstr("operator 'fixture.fill' is defined twice"));
  EXPECT_THAT(message, HasSubstr(fixture_dir("good") + "/libfixture_ops.so"));
  EXPECT_THAT(message, HasSubstr(fixture_dir("dup") + "/libfixture_dup.so"));
}

TEST(OperatorRegistry, FindsOperatorsOfEachKind) {
  const OperatorRegistry& r = test::fixture_registry();
  ASSERT_EQ(r.modules().size(), 1u);
  EXPECT_EQ(r.find("fixture.blur")->spec().kind, OperatorKind::Cell);
  EXPECT_EQ(r.find("fixture.sum")->spec().kind, OperatorKind::Reduce);
  EXPECT_EQ(r.find("fixture.region_scan")->spec().kind, OperatorKind::Region);
  EXPECT_EQ(r.find("fixture.nope"), nullptr);
}

TEST(OperatorRegistry, ListsModulesAsJsonAndText) {
  const OperatorRegistry& r = test::fixture_registry();
  const auto j = r.to_json();
  ASSERT_EQ(j.size(), 1u);
  EXPECT_EQ(j[0]["name"], "fixture");
  EXPECT_EQ(j[0]["version"], "0.0.1");
  EXPECT_EQ(j[0]["file"], fixture_dir("good") + "/libfixture_ops.so");
  ASSERT_EQ(j[0]["operators"].size(), 11u);
  const auto& blur = j[0]["operators"][1];
  EXPECT_EQ(blur["name"], "fixture.blur");
  EXPECT_EQ(blur["kind"], "cell");
  EXPECT_EQ(blur["halo"], 1);
  EXPECT_EQ(blur["inputs"][0]["name"], "src");
  EXPECT_EQ(blur["outputs"][0]["dtype"], "float32");
  EXPECT_EQ(blur["outputs"][0]["semantics"], "continuous");
  EXPECT_EQ(blur["outputs"][0]["nodata"], -9999);
  EXPECT_EQ(blur["params"]["properties"]["sleep_ms"]["default"], 0);
  EXPECT_EQ(blur["inputs"][0]["kind"], "raster");
  const auto& near = j[0]["operators"][4];
  EXPECT_EQ(near["name"], "fixture.near_features");
  EXPECT_EQ(near["inputs"][0]["kind"], "features");
  EXPECT_EQ(near["inputs"][0]["reach_m"], 1000);
  const auto& content = j[0]["operators"][7];
  EXPECT_EQ(content["name"], "fixture.content");
  EXPECT_EQ(content["outputs"][0]["kind"], "mesh");
  EXPECT_EQ(content["outputs"][1]["kind"], "instances");
  EXPECT_EQ(content["outputs"][2]["kind"], "volume");
  EXPECT_EQ(j[0]["operators"][8]["kind"], "region");

  std::ostringstream text;
  r.print(text);
  EXPECT_THAT(text.str(), HasSubstr("fixture 0.0.1: Operators for the runtime tests"));
  EXPECT_THAT(text.str(), HasSubstr("fixture.blur (cell, halo 1)"));
  EXPECT_THAT(text.str(), HasSubstr("output dst float32 x1 continuous nodata -9999.0: the result"));
  EXPECT_THAT(text.str(), HasSubstr("fixture.sum (reduce)"));
  EXPECT_THAT(text.str(), HasSubstr("input  strokes (features within 1000.0 m): features layer"));
  EXPECT_THAT(text.str(), HasSubstr("seed number (required)"));
  EXPECT_THAT(text.str(), HasSubstr("sleep_ms integer = 0 [0..10000]"));
}

}  // namespace
}  // namespace maquette
