// synthesis.transfer's and synthesis.assess's params checked when the pipeline is read
// (exemplar_params_check.h), through the real program: a painting path mistyped, a class count
// beside a class image, a harmonization with one painting, a further painting's missing class
// image, the patch passes' fields without the passes are refused before the ingest step before
// them runs (no store is made), naming the step, field and file; --dry-run tells them too; a
// pipeline that is right passes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "run_cli.h"
#include "synthetic_raster.h"

namespace maquette::synthesis {
namespace {

using json = nlohmann::json;

struct Fixture {
  std::string dir = test::temp_dir();
  std::string painting = test::write_png(dir + "/painting.png", 64, 64, 3,
                                         [](int x, int y, int b) { return 40 * b + x + y; });
  std::string classes = test::write_png(dir + "/classes.png", 64, 64, 1,
                                        [](int x, int, int) { return x < 32 ? 0 : 1; });
  std::string landcover = dir + "/landcover.tif";

  Fixture() {
    test::write_raster(landcover, test::lonlat_raster(-113.0, 37.2, 64, 0.001, "Byte"),
                       [](int, double x, double) { return x < -112.968 ? 1 : 2; });
  }

  // A pipeline ingesting the land cover, then step 2: `op` with `params` added to a painting's.
  std::string pipeline(const std::string& name, const std::string& op, const json& params) const {
    json p = {{"painting", painting}, {"classes", 2}, {"landcover_classes", {{"1", 0}, {"2", 1}}}};
    p.update(params);
    json step = {{"op", op}, {"inputs", {{"landcover", "landcover"}}}, {"params", p}};
    if (op == "synthesis.transfer")
      step["outputs"] = {{"rgb", "painted"}};
    else {
      step["inputs"]["rgb"] = "painted";
      step["inputs"]["source"] = "source";
      step["outputs"] = {{"report", "assessment"}};
    }
    const json doc = {{"store", dir + "/" + name + ".mqt"},
                      {"region", {{"bbox", {-113.0, 37.14, -112.94, 37.2}}}},
                      {"level", 9},
                      {"steps",
                       {{{"op", "ingest"},
                         {"outputs", {{"layer", "landcover"}}},
                         {"params", {{"sources", {landcover}}, {"as", "landcover"}, {"level", 9}}}},
                        step}}};
    const std::string path = dir + "/" + name + ".json";
    std::ofstream(path) << doc.dump(1);
    return path;
  }

  // Runs the pipeline (and its dry run): both refuse it with a message holding each of `says`,
  // and no store is made.
  void refused(const std::string& name, const std::string& op, const json& params,
               const std::vector<std::string>& says) const {
    const std::string path = pipeline(name, op, params);
    for (const char* mode : {"--dry-run ", ""}) {
      const auto r =
          test::run_maquette("run " + std::string(mode) + path, "MAQUETTE_CACHE_DIR=off");
      EXPECT_NE(r.exit_code, 0) << name << " " << mode << r.out;
      for (const std::string& s : says) EXPECT_NE(r.err.find(s), std::string::npos) << r.err;
      EXPECT_FALSE(std::filesystem::exists(dir + "/" + name + ".mqt")) << name;
    }
  }
};

TEST(ExemplarParamsCheck, AMistypedPaintingIsToldBeforeAnyStepRuns) {
  const Fixture f;
  f.refused("missing", "synthesis.transfer", {{"painting", f.dir + "/paintng.png"}},
            {"step 2 (synthesis.transfer)", f.dir + "/paintng.png",
             "the painting (painting): no such file"});
  f.refused("empty", "synthesis.transfer", {{"painting", ""}},
            {"step 2 (synthesis.transfer)", "the painting (painting): an empty path"});
  f.refused("relative", "synthesis.transfer", {{"painting", "paintng.png"}},
            {"paintng.png: the painting (painting): no such file (relative to the working "
             "directory"});
  f.refused("assessed", "synthesis.assess", {{"exclusion", f.dir + "/mask.png"}},
            {"step 2 (synthesis.assess)", f.dir + "/mask.png",
             "the exclusion mask (exclusion): no such file"});
  f.refused("further", "synthesis.transfer",
            {{"exemplars",
              {{{"painting", f.painting},
                {"labels", f.dir + "/classes2.png"},
                {"landcover_classes", {{"1", 1}}}}}}},
            {f.dir + "/classes2.png", "the class image (exemplars[0].labels): no such file"});
}

TEST(ExemplarParamsCheck, FieldsThatWouldDoNothingAreRefused) {
  const Fixture f;
  f.refused("beside", "synthesis.transfer", {{"labels", f.classes}, {"classes", 8}},
            {"synthesis.transfer.classes: 8 is the k of the segmentation by colour, which the "
             "class image",
             f.classes});
  f.refused("further_beside", "synthesis.transfer",
            {{"exemplars",
              {{{"painting", f.painting},
                {"labels", f.classes},
                {"classes", 3},
                {"landcover_classes", {{"1", 1}}}}}}},
            {"synthesis.transfer.exemplars[0].classes: 3 is the k of the segmentation"});
  f.refused("harmonized", "synthesis.transfer", {{"harmonize", "histogram"}},
            {"synthesis.transfer.harmonize: \"histogram\" matches further paintings' colours",
             "there are none"});
  f.refused("table", "synthesis.transfer",
            {{"exemplars", {{{"painting", f.painting}, {"landcover_classes", {{"7", 1}}}}}}},
            {"target value 7 is not in the first painting's landcover_classes"});
  f.refused("further_altitude", "synthesis.transfer",
            {{"painting_altitude", "rows"},
             {"exemplars", {{{"painting", f.painting}, {"landcover_classes", {{"1", 1}}}}}}},
            {"synthesis.transfer.exemplars[0].painting_altitude: missing, but the first painting "
             "has one"});
  f.refused("altitude", "synthesis.transfer", {{"altitude_range", {1000, 2000}}},
            {"synthesis.transfer.altitude_range is given without inputs.dem"});
  f.refused("lines", "synthesis.transfer", {{"line_classes", {1}}},
            {"synthesis.transfer.line_classes [1] keep lines through the patch passes, and "
             "patch_passes is 0"});
  f.refused("edges", "synthesis.transfer", {{"patch_edges", 3}},
            {"synthesis.transfer.patch_edges: 3 is a field of the patch passes, and patch_passes "
             "is 0"});
  f.refused("balance", "synthesis.transfer", {{"patch_balance", 0.25}},
            {"synthesis.transfer.patch_balance: 0.25 is a field of the patch passes"});
}

TEST(ExemplarParamsCheck, ARightPipelinePassesItsDryRun) {
  const Fixture f;
  // The class image beside the default class count, one painting with the default harmonization,
  // the passes with their fields.
  const auto r = test::run_maquette("run --dry-run " + f.pipeline("right", "synthesis.transfer",
                                                                  {{"labels", f.classes},
                                                                   {"classes", 6},
                                                                   {"harmonize", "reinhard"},
                                                                   {"patch_passes", 1},
                                                                   {"patch_search", 2},
                                                                   {"patch_edges", 2},
                                                                   {"patch_balance", 0.25}}),
                                    "MAQUETTE_CACHE_DIR=off");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("step 2 (synthesis.transfer)"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace maquette::synthesis
