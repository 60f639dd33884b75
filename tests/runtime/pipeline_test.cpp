#include "runtime/pipeline.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "runtime/runner.h"
#include "test_util.h"

namespace maquette {
namespace {

using nlohmann::json;
using test::demo_pipeline;
using test::error_of;
using ::testing::HasSubstr;

Pipeline parse(const json& doc) {
  return parse_pipeline(doc.dump(), "p.json", "/base", test::fixture_registry());
}
std::string parse_error(const json& doc) {
  return error_of([&] { parse(doc); });
}

TEST(Pipeline, ParsesStepsRegionAndPaths) {
  const Pipeline p = parse(demo_pipeline());
  EXPECT_EQ(p.store_path, "/base/out.mqt");
  EXPECT_EQ(p.level, 4);
  EXPECT_EQ(p.tile_size, 16);
  EXPECT_EQ(p.region.size(), 64u);  // Q2 at level 4
  EXPECT_TRUE(std::is_sorted(p.region.begin(), p.region.end()));
  ASSERT_EQ(p.steps.size(), 4u);
  EXPECT_EQ(p.steps[1].label(), "step 2 (fixture.blur)");
  EXPECT_EQ(p.steps[1].inputs.at("src"), "height");
  EXPECT_EQ(p.steps[0].params.at("mode"), "wave");  // default filled in
}

TEST(Pipeline, RegionFromBboxGeojsonAndCells) {
  json doc = demo_pipeline();
  doc["region"] = {{"bbox", {0, 0, 10, 10}}};
  EXPECT_FALSE(parse(doc).region.empty());
  doc["region"] = {{"geojson", json::parse(R"({"type": "Feature", "geometry": {"type": "Polygon",
      "coordinates": [[[0, 0], [10, 0], [10, 10], [0, 0]]]}})")}};
  EXPECT_FALSE(parse(doc).region.empty());
  doc["region"] = {{"cells", {"Q20", "Q2000000"}}};  // finer cells map to their ancestor
  const Pipeline p = parse(doc);
  EXPECT_EQ(p.region.size(), 16u);
  EXPECT_EQ(p.region.front().ToText(), "Q2000");
}

// A GeoJSON object without its geometry or coordinates let nlohmann's out_of_range escape
// (fuzz/corpus/geojson/regress-*, fuzz/corpus/pipeline/regress-*).
TEST(Pipeline, RegionGeojsonWithoutItsMembersIsNamed) {
  json doc = demo_pipeline();
  doc["region"] = {{"geojson", {{"type", "Feature"}, {"properties", json::object()}}}};
  EXPECT_THAT(parse_error(doc), HasSubstr(": a Feature has no \"geometry\""));
  doc["region"] = {{"geojson", {{"type", "MultiPolygon"}}}};
  EXPECT_THAT(parse_error(doc), HasSubstr(": a MultiPolygon has no \"coordinates\""));
}

TEST(Pipeline, MalformedJsonNamesLineAndColumn) {
  const std::string message = error_of([] {
    parse_pipeline("{\"store\": \"x.mqt\",\n  \"level\": 4,,\n}", "p.json", ".",
                   test::fixture_registry());
  });
  EXPECT_THAT(message, ::testing::StartsWith("p.json: parse error at line 2, column 14"));
}

TEST(Pipeline, UnknownOperator) {
  json doc = demo_pipeline();
  doc["steps"][1]["op"] = "fixture.blurr";
  EXPECT_THAT(parse_error(doc),
              ::testing::StartsWith(
                  "p.json: step 2 (fixture.blurr): op: unknown operator 'fixture.blurr'"));
}

TEST(Pipeline, MissingOrWrongTypedParameter) {
  json doc = demo_pipeline();
  doc["steps"][0]["params"].erase("seed");
  EXPECT_EQ(parse_error(doc),
            "p.json: step 1 (fixture.fill): params: missing required field 'seed'");
  doc["steps"][0]["params"]["seed"] = "abc";
  EXPECT_EQ(parse_error(doc),
            "p.json: step 1 (fixture.fill): params.seed: expected a number, got \"abc\"");
  doc["steps"][0]["params"]["seed"] = 1;
  doc["steps"][1]["params"]["sleep_ms"] = 20000;
  EXPECT_EQ(parse_error(doc),
            "p.json: step 2 (fixture.blur): params.sleep_ms: 20000 is above the maximum 10000");
}

TEST(Pipeline, PortErrors) {
  json doc = demo_pipeline();
  doc["steps"][1]["inputs"] = {{"source", "height"}};
  EXPECT_THAT(parse_error(doc),
              HasSubstr("p.json: step 2 (fixture.blur): inputs.source: unknown input port"));
  doc["steps"][1]["inputs"] = json::object();
  EXPECT_EQ(parse_error(doc),
            "p.json: step 2 (fixture.blur): inputs: missing required input 'src'");
  doc = demo_pipeline();
  doc["steps"][1]["outputs"] = json::object();
  EXPECT_EQ(parse_error(doc), "p.json: step 2 (fixture.blur): outputs: map at least one of: dst");
  doc["steps"][1]["outputs"] = {{"dst", "height"}};
  EXPECT_EQ(parse_error(doc),
            "p.json: step 2 (fixture.blur): outputs.dst: layer 'height' is also the step's input");
  doc["steps"][1]["outputs"] = {{"dst", "scan"}};
  EXPECT_EQ(parse_error(doc),
            "p.json: step 4 (fixture.region_scan): outputs.dst: layer 'scan' is already written by "
            "step 2");
  doc = demo_pipeline();
  doc["steps"][1]["param"] = json::object();
  EXPECT_EQ(parse_error(doc), "p.json: step 2 (fixture.blur): unknown field 'param'");
}

TEST(Pipeline, InvalidCellIdLevelAndLatitude) {
  json doc = demo_pipeline();
  doc["region"] = {{"cells", {"Q2", "Q9"}}};
  EXPECT_EQ(parse_error(doc), "p.json: region.cells[1]: \"Q9\" is not a valid cell id");
  doc = demo_pipeline();
  doc["level"] = 30;
  EXPECT_EQ(parse_error(doc), "p.json: level: 30 is outside 0..29");
  doc["level"] = 4294967300;  // 4 when truncated to 32 bits
  EXPECT_EQ(parse_error(doc), "p.json: level: 4294967300 is outside 0..29");
  doc["level"] = -18446744073709551;
  EXPECT_EQ(parse_error(doc), "p.json: level: -18446744073709551 is outside 0..29");
  doc["level"] = "8";
  EXPECT_EQ(parse_error(doc), "p.json: level: expected an integer, got \"8\"");
  doc = demo_pipeline();
  doc["region"] = {{"bbox", {0, -95, 10, 10}}};
  EXPECT_EQ(parse_error(doc), "p.json: region.bbox: latitude -95 is outside -90..90");
  doc["region"] = {{"circle", 1}};
  EXPECT_THAT(parse_error(doc), HasSubstr("p.json: region: unknown field 'circle'"));
  doc = demo_pipeline();
  doc["tile_size"] = 100;
  EXPECT_EQ(
      parse_error(doc),
      "p.json: tile_size: tile size 100 is not a power of two in [2, 4096] (a layer's overviews "
      "halve its tiles)");
  doc["tile_size"] = 1;  // its layers' overviews could not halve it (the run failed at its end)
  EXPECT_EQ(
      parse_error(doc),
      "p.json: tile_size: tile size 1 is not a power of two in [2, 4096] (a layer's overviews "
      "halve its tiles)");
  doc["tile_size"] = 4294967312;  // 16 when truncated to 32 bits
  EXPECT_EQ(parse_error(doc), "p.json: tile_size: 4294967312 is outside -2147483648..2147483647");
  doc.erase("store");
  EXPECT_EQ(parse_error(doc), "p.json: store: missing required field");
}

TEST(Pipeline, UnknownLayerIsFoundBeforeAnythingRuns) {
  test::TempDir dir;
  json doc = demo_pipeline();
  doc["steps"][1]["inputs"]["src"] = "hieght";
  const std::string file = test::write_pipeline(dir, doc);
  const Pipeline p = test::load_fixture_pipeline(file);
  const std::string store = dir.file("out.mqt");
  EXPECT_EQ(error_of([&] { run_pipeline(p, RunOptions{}); }),
            file + ": step 2 (fixture.blur): inputs.src: unknown layer 'hieght' in " + store);
  EXPECT_FALSE(std::filesystem::exists(store));
}

TEST(Pipeline, RefineOnlyForRefinableCellOperators) {
  json doc = demo_pipeline();
  doc["steps"][1]["refine"] = 2;
  EXPECT_EQ(parse_error(doc),
            "p.json: step 2 (fixture.blur): refine: the operator writes its outputs at its inputs' "
            "resolution only (not refinable)");
  doc["steps"][1]["refine"] = 13;
  EXPECT_EQ(parse_error(doc), "p.json: step 2 (fixture.blur): refine: 13 is outside 0..12");
  doc["steps"][1]["refine"] = "2";
  EXPECT_EQ(parse_error(doc),
            "p.json: step 2 (fixture.blur): refine: expected an integer, got \"2\"");
  doc["steps"][1]["refine"] = 0;  // allowed everywhere: the inputs' resolution
  EXPECT_EQ(parse(doc).steps[1].refine, 0);
}

// {"$artifact": NAME} in params: checked before anything runs, pasted in (and validated) when
// the step runs.
TEST(Pipeline, ArtifactReferencesInParams) {
  test::TempDir dir;
  json doc = demo_pipeline();
  json fill = doc["steps"][0];
  fill["outputs"] = {{"value", "again"}};
  fill["params"]["weights"] = {{"$artifact", "smooth_sum"}};
  doc["steps"].push_back(fill);
  const std::string file = test::write_pipeline(dir, doc);
  const Pipeline p = test::load_fixture_pipeline(file);
  RunOptions options;
  options.quiet = true;
  // fixture.sum's artifact is {"count": ..., "sum": ...}, not the array of numbers "weights" is.
  EXPECT_THAT(error_of([&] { run_pipeline(p, options); }),
              ::testing::MatchesRegex(
                  ".*/pipeline.json: step 5 \\(fixture.fill\\): params.weights: expected an "
                  "array, got \\{\"count\":16384,\"sum\":.*\\}"));

  doc["steps"][4]["params"]["weights"] = {{"$artifact", "smooth_total"}};
  const Pipeline typo = test::load_fixture_pipeline(test::write_pipeline(dir, doc));
  EXPECT_EQ(
      error_of([&] { run_pipeline(typo, options); }),
      file + ": step 5 (fixture.fill): params.weights: unknown artifact 'smooth_total' (not in " +
          dir.file("out.mqt") + " nor written by an earlier step)");
}

// A part of an artifact: fixture.sum's count as fixture.fill's seed gives the tiles of that seed
// written as a number; a pointer to nothing is named.
TEST(Pipeline, ArtifactPartsByJsonPointer) {
  RunOptions options;
  options.quiet = true;
  auto fill_again = [](const json& seed) {
    json doc = demo_pipeline();
    json fill = doc["steps"][0];
    fill["outputs"] = {{"value", "again"}};
    fill["params"]["seed"] = seed;
    doc["steps"].push_back(fill);
    return doc;
  };
  test::TempDir by_ref, by_value;
  run_pipeline(test::load_fixture_pipeline(test::write_pipeline(
                   by_ref, fill_again({{"$artifact", "smooth_sum"}, {"pointer", "/count"}}))),
               options);
  run_pipeline(
      test::load_fixture_pipeline(test::write_pipeline(by_value, fill_again(64 * 16 * 16))),
      options);
  const test::Snapshot a = test::snapshot(by_ref.file("out.mqt"));
  const test::Snapshot b = test::snapshot(by_value.file("out.mqt"));
  EXPECT_EQ(test::first_difference(a, b), "");
  EXPECT_EQ(a.count("again/Q2000"), 1u);

  test::TempDir bad;
  const std::string file =
      test::write_pipeline(bad, fill_again({{"$artifact", "smooth_sum"}, {"pointer", "/total"}}));
  EXPECT_THAT(
      error_of([&] { run_pipeline(test::load_fixture_pipeline(file), options); }),
      ::testing::StartsWith(file + ": step 5 (fixture.fill): params.seed.pointer: \"/total\" in "
                                   "artifact 'smooth_sum': "));
}

// An operator's check_params (fixture.fill: a seed under 20000) runs when the pipeline is read,
// its message prefixed with the step; on an artifact's value once it is pasted in, before the
// step runs (and after the steps before it).
TEST(Pipeline, TheOperatorsCheckOfItsParamsRunsBeforeAnythingRuns) {
  json doc = demo_pipeline();
  doc["steps"][0]["params"]["seed"] = 20000;
  EXPECT_EQ(
      parse_error(doc),
      "p.json: step 1 (fixture.fill): params.seed: 20000 is 20000 or more (the fixture's check)");

  doc = demo_pipeline();
  doc["tile_size"] = 32;
  json fill = doc["steps"][0];
  fill["outputs"] = {{"value", "again"}};
  fill["params"]["seed"] = {{"$artifact", "smooth_sum"}, {"pointer", "/count"}};  // 64 x 32^2
  doc["steps"].push_back(fill);
  test::TempDir dir;
  const std::string file = test::write_pipeline(dir, doc);
  RunOptions options;
  options.quiet = true;
  EXPECT_EQ(
      error_of([&] { run_pipeline(test::load_fixture_pipeline(file), options); }),
      file + ": step 5 (fixture.fill): params.seed: 65536 is 20000 or more (the fixture's check)");
}

TEST(Pipeline, DryRunPrintsThePlanAndWritesNothing) {
  test::TempDir dir;
  const Pipeline p = test::load_fixture_pipeline(test::write_pipeline(dir, demo_pipeline()));
  std::ostringstream out;
  RunOptions options;
  options.dry_run = true;
  const RunSummary summary = run_pipeline(p, options, out);
  EXPECT_FALSE(std::filesystem::exists(dir.file("out.mqt")));
  ASSERT_EQ(summary.steps.size(), 4u);
  for (const auto& s : summary.steps) EXPECT_EQ(s.cells, 64);
  EXPECT_THAT(out.str(), HasSubstr("step 2 (fixture.blur): cell operator, 64 cells at level 4"));
  EXPECT_THAT(out.str(), HasSubstr("writes smooth (dst: float32 x1, 64 tiles of 16px)"));
  EXPECT_THAT(out.str(), HasSubstr("writes artifact smooth_sum"));
}

}  // namespace
}  // namespace maquette
