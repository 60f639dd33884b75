// synthesis.assess run by the real program after synthesis.transfer on Zion's land cover and
// DEM (../shared/data) with Bruegel's painting (8 colour classes, the sky's excluded, exemplar
// scale 4: 45,670 usable exemplar pixels for the 131,072 output pixels of 2 cells, so a
// distinct-source fraction of 0.3 is within reach: at most 0.348). The report's counts of sources
// are checked against a count of the stored source tiles, and issue 18's measures are gated at what
// the transfer meets now (NOTES.md: synthesis.assess, beside the goals). And with a second
// painting, The Starry Night: the sources counted by painting, column and row. And the one-painting
// example's weights, gated at their own levels.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "core/tile.h"
#include "run_cli.h"
#include "store/store.h"
#include "zion_ingest.h"

namespace maquette::synthesis {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Gates at the measures of the transfer with the exemplar's measured over-use and the blocks'
// preferences (synthesis.h: D_usage, D_spread; label consistency 1, distinct sources 0.0964, most
// used source 0.346 %, worst label histogram 0.328, coherence 16,231 with the k similar patches
// searched approximately (0.0965, 0.337 %, 0.328 and 16,237 exactly), altitude mismatch 0.179;
// before them, with the vote of radius 1: 0.093, 0.50 %, 0.337, 15,682 and 0.161; without the
// vote 0.089, 0.47 %, 0.301, 16,639 and 0.163), each with a small margin.
constexpr double kLabelGate = 0.995, kDistinctGate = 0.09, kMaxShareGate = 0.004;
constexpr double kHistogramGate = 0.35, kCoherenceGate = 17000, kAltitudeGate = 0.19;

// The exemplar and guides, the same for the transfer and its assessment.
json transfer_params() {
  return {{"painting", kPainting},
          {"classes", 8},
          {"exclude_classes", {0}},
          {"landcover_classes",
           {{"1", 7}, {"2", 3}, {"3", 5}, {"4", 6}, {"5", 7}, {"6", 2}, {"7", 2}, {"8", 6}}},
          {"painting_altitude", "rows"},
          {"altitude_range", {1100, 2700}},
          {"exemplar_scale", 4}};
}

// Zion ingested, synthesis.transfer with `params` and `weights` (the synthesis's own fields) and
// synthesis.assess with `params` (coherence at every 4th column and row) run by the real program
// into `store`; the report. Both steps are given the DEM unless `dem` is false.
json transfer_and_assess(const json& params, const fs::path& dir, const std::string& store,
                         bool dem = true, const json& weights = json::object()) {
  json transfer = params;
  transfer.update(weights);
  json assess = params;
  assess["coherence_step"] = 4;
  json transfer_inputs = {{"landcover", "landcover"}},
       assess_inputs = {
           {"rgb", "painted"}, {"source", "painted_source"}, {"landcover", "landcover"}};
  if (dem) transfer_inputs["dem"] = assess_inputs["dem"] = "dem";
  json pipeline = {{"store", store},
                   {"region", {{"bbox", {-113.03, 37.25, -113.025, 37.255}}}},
                   {"level", 10},
                   {"steps",
                    {{{"op", "synthesis.transfer"},
                      {"inputs", transfer_inputs},
                      {"outputs", {{"rgb", "painted"}, {"source", "painted_source"}}},
                      {"params", transfer}},
                     {{"op", "synthesis.assess"},
                      {"inputs", assess_inputs},
                      {"outputs", {{"report", "assessment"}}},
                      {"params", assess}}}}};
  const json ingest = zion_ingest_steps();
  pipeline["steps"].insert(pipeline["steps"].begin(), ingest.begin(), ingest.end());
  const fs::path path = dir / "pipeline.json";
  std::ofstream(path) << pipeline.dump(1);
  const test::CliResult r = test::run_maquette("run " + path.string() + " --quiet --threads 2");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  if (r.exit_code != 0) return nullptr;
  return json::parse(Store::open(store, Store::Mode::ReadOnly)->get_artifact("assessment")->text());
}

// The sources counted again from the stored tiles: output pixels per painting pixel (painting,
// column, row; the painting 0 when the layer has no third channel).
using Uses = std::map<std::array<int, 3>, uint64_t>;

Uses stored_uses(const std::string& store) {
  const auto s = Store::open(store, Store::Mode::ReadOnly);
  Uses uses;
  for (const CellId cell : s->tile_cells("painted_source")) {
    const Tile<float> source = to_tile<float>(*s->get_tile("painted_source", cell));
    for (int row = 0; row < source.size(); ++row)
      for (int col = 0; col < source.size(); ++col)
        if (!std::isnan(source.at(col, row, 0)))
          ++uses[{source.channels() > 2 ? int(source.at(col, row, 2)) : 0,
                  int(source.at(col, row, 0)), int(source.at(col, row, 1))}];
  }
  return uses;
}

// The report's pixels, distinct-source fraction and most used source's share are those of the
// stored sources; returns the pixels.
uint64_t expect_the_stored_sources(const json& report, const Uses& uses) {
  uint64_t pixels = 0, most = 0;
  for (const auto& [where, n] : uses) pixels += n, most = std::max(most, n);
  EXPECT_EQ(report.at("pixels").get<uint64_t>(), pixels);
  EXPECT_DOUBLE_EQ(report.at("distinct_source_fraction").get<double>(),
                   double(uses.size()) / double(pixels));
  EXPECT_DOUBLE_EQ(report.at("max_source_share").get<double>(), double(most) / double(pixels));
  return pixels;
}

TEST(AssessZion, ReportsTheTransfersMeasuresAtTheirCurrentLevels) {
  if (!fs::exists(kPainting) || !fs::exists(kShared + "/zion/nlcd.tif"))
    GTEST_SKIP() << "../shared/data is absent";
  const fs::path dir = test::temp_dir();
  const std::string store = (dir / "zion.mqt").string();
  const json report = transfer_and_assess(transfer_params(), dir, store);
  ASSERT_FALSE(report.is_null());
  const uint64_t pixels = expect_the_stored_sources(report, stored_uses(store));
  EXPECT_GE(report.at("distinct_source_bound").get<double>(), 0.3);  // 0.3 is reachable
  // With every pixel's label kept (below), the fraction is under the label bound, itself under
  // the bound.
  EXPECT_LE(report.at("distinct_source_fraction").get<double>(),
            report.at("distinct_source_label_bound").get<double>());
  EXPECT_LE(report.at("distinct_source_label_bound").get<double>(),
            report.at("distinct_source_bound").get<double>());
  // A sample of every 4th column and row, less the patches reaching beyond the region.
  EXPECT_GT(report.at("coherence_patches").get<uint64_t>(), pixels / 17);
  EXPECT_LE(report.at("coherence_patches").get<uint64_t>(), pixels / 16);

  std::printf("assessment: %s\n", report.dump().c_str());
  // Issue 18's measures at what is met now (NOTES.md): the exclusion and label goals are met; the
  // others are gated at their current level so that a regression shows.
  EXPECT_EQ(report.at("excluded_pixels").get<uint64_t>(), 0u);                     // goal: 0
  EXPECT_GE(report.at("label_consistency").get<double>(), kLabelGate);             // goal: 0.97
  EXPECT_GE(report.at("distinct_source_fraction").get<double>(), kDistinctGate);   // goal: 0.3
  EXPECT_LE(report.at("max_source_share").get<double>(), kMaxShareGate);           // goal: 0.0005
  EXPECT_LE(report.at("worst_histogram_distance").get<double>(), kHistogramGate);  // goal: 0.25
  EXPECT_LE(report.at("coherence").get<double>(), kCoherenceGate);  // goal: 2 x ebsynth's
  EXPECT_LE(report.at("altitude_mismatch").get<double>(), kAltitudeGate);
}

// The one-painting example's weights (examples/synthesis-zion.json: the patch passes, draws from
// the painting's class edges, the vote of radius 2 with its balance, strong block preferences on
// typical regions only, the developed class as lines) on the same cells, gated at what they meet
// now, each with a small margin: coherence 13,746 (the defaults' 16,231), distinct 0.0836, most
// used 0.299 % (0.346 %), worst histogram 0.452 (class 2, the golden wheat, a few fields here;
// the defaults' 0.328), altitude mismatch 0.176.
constexpr double kExampleCoherenceGate = 14500, kExampleDistinctGate = 0.078;
constexpr double kExampleMaxShareGate = 0.0035, kExampleHistogramGate = 0.48;
TEST(AssessZion, TheExamplesWeightsAtTheirCurrentLevels) {
  if (!fs::exists(kPainting) || !fs::exists(kShared + "/zion/nlcd.tif"))
    GTEST_SKIP() << "../shared/data is absent";
  const json example = json::parse(
      std::ifstream(std::string(MAQUETTE_SOURCE_DIR) + "/examples/synthesis-zion.json"));
  json weights;
  for (const json& step : example.at("steps"))
    if (step.at("op") == "synthesis.transfer")
      for (const auto& [field, value] : step.at("params").items())
        if (!transfer_params().contains(field))
          weights[field] = value;  // the exemplar's: this test's
  ASSERT_TRUE(weights.contains("patch_passes")) << weights.dump();
  const fs::path dir = test::temp_dir();
  const std::string store = (dir / "zion.mqt").string();
  const json report = transfer_and_assess(transfer_params(), dir, store, true, weights);
  ASSERT_FALSE(report.is_null());
  std::printf("weights: %s\nassessment: %s\n", weights.dump().c_str(), report.dump().c_str());
  EXPECT_EQ(report.at("excluded_pixels").get<uint64_t>(), 0u);
  EXPECT_GE(report.at("label_consistency").get<double>(), kLabelGate);
  EXPECT_LE(report.at("coherence").get<double>(), kExampleCoherenceGate);
  EXPECT_GE(report.at("distinct_source_fraction").get<double>(), kExampleDistinctGate);
  EXPECT_LE(report.at("max_source_share").get<double>(), kExampleMaxShareGate);
  EXPECT_LE(report.at("worst_histogram_distance").get<double>(), kExampleHistogramGate);
  EXPECT_LE(report.at("altitude_mismatch").get<double>(), kAltitudeGate);
}

TEST(AssessZion, WithoutAnAltitudeGuideNoAltitudeMismatchIsReported) {
  if (!fs::exists(kPainting) || !fs::exists(kShared + "/zion/nlcd.tif"))
    GTEST_SKIP() << "../shared/data is absent";
  json params = transfer_params();
  params.erase("painting_altitude");
  params.erase("altitude_range");
  const fs::path dir = test::temp_dir();
  const json report = transfer_and_assess(params, dir, (dir / "zion.mqt").string(), false);
  ASSERT_FALSE(report.is_null());
  EXPECT_GT(report.at("pixels").get<uint64_t>(), 0u);
  // Not 0, which would read as a perfect match (ReportsTheTransfersMeasures... has it).
  EXPECT_FALSE(report.contains("altitude_mismatch")) << report.dump();
}

// An assessment given other exemplar params than the transfer that made its source layer measured
// against another analysis, silently (exemplar_scale 8 against 4: coherence 13,750 instead of
// 15,847), or reading the target through another table or altitude range: refused, naming the
// field; differently spelled but equal values (the default k given, a class as a set of one)
// pass.
TEST(AssessZion, ParamsOfAnotherExemplarThanTheTransfersAreRefused) {
  if (!fs::exists(kPainting) || !fs::exists(kShared + "/zion/nlcd.tif"))
    GTEST_SKIP() << "../shared/data is absent";
  const fs::path dir = test::temp_dir();
  const std::string store = (dir / "zion.mqt").string();
  ASSERT_FALSE(transfer_and_assess(transfer_params(), dir, store).is_null());
  auto assess_again = [&](const json& params) {
    const json pipeline = {{"store", store},
                           {"region", {{"bbox", {-113.03, 37.25, -113.025, 37.255}}}},
                           {"level", 10},
                           {"steps",
                            {{{"op", "synthesis.assess"},
                              {"inputs",
                               {{"rgb", "painted"},
                                {"source", "painted_source"},
                                {"landcover", "landcover"},
                                {"dem", "dem"}}},
                              {"outputs", {{"report", "again"}}},
                              {"params", params}}}}};
    const fs::path path = dir / "again.json";
    std::ofstream(path) << pipeline.dump(1);
    return test::run_maquette("run " + path.string() + " --quiet");
  };
  json other = transfer_params();
  other["exemplar_scale"] = 8;
  const test::CliResult refused = assess_again(other);
  EXPECT_NE(refused.exit_code, 0);
  EXPECT_NE(refused.err.find("synthesis.assess: its params differ from those "
                             "synthesis.transfer made layer 'painted_source' with (exemplar_scale: "
                             "the transfer's 4, assess's 8)"),
            std::string::npos)
      << refused.err;
  // The same classes for other land-cover values, and another altitude range: the measures would
  // read the target otherwise than the transfer did (label consistency 0.23 for this table).
  json table = transfer_params();
  table["landcover_classes"] = {{"1", 6}, {"2", 7}, {"3", 5}, {"4", 7},
                                {"5", 6}, {"6", 3}, {"7", 3}, {"8", 2}};
  const test::CliResult other_table = assess_again(table);
  EXPECT_NE(other_table.exit_code, 0);
  EXPECT_NE(other_table.err.find("landcover_classes: the transfer's {\"1\":7,"), std::string::npos)
      << other_table.err;
  json range = transfer_params();
  range["altitude_range"] = {1000, 3000};
  const test::CliResult other_range = assess_again(range);
  EXPECT_NE(other_range.exit_code, 0);
  EXPECT_NE(
      other_range.err.find("altitude_range: the transfer's [1100,2700], assess's [1000,3000]"),
      std::string::npos)
      << other_range.err;
  json same = transfer_params();
  same["k"] = 2;                         // its default
  same["landcover_classes"]["2"] = {3};  // a set of one: the same table
  const test::CliResult passed = assess_again(same);
  EXPECT_EQ(passed.exit_code, 0) << passed.err;
}

// With a second painting (The Starry Night, classed by hand, the benchmark's table;
// benchmarks/README.md) the assessment reads the source layer's third channel, the painting: the
// sources counted from the stored tiles by painting, column and row give the report's pixels,
// distinct fraction and most used share, both paintings are copied, and the same column and row
// of the two paintings are two sources (the count without the painting is smaller). No excluded
// pixel of either painting, and every source of the target's class through both tables.
TEST(AssessZion, CountsTheSourcesOfBothPaintings) {
  const std::string starry = std::string(MAQUETTE_BIN_DIR) + "/../demo-data/starry_night.jpg";
  if (!fs::exists(kPainting) || !fs::exists(kShared + "/zion/nlcd.tif"))
    GTEST_SKIP() << "../shared/data is absent";
  if (!fs::exists(starry))
    GTEST_SKIP() << starry << " is absent: scripts/setup.sh fetches it (Debian's opencv-doc)";
  json params = transfer_params();
  params["exemplars"] = {
      {{"painting", starry},
       {"labels", std::string(MAQUETTE_SOURCE_DIR) + "/examples/starry-night-classes.geojson"},
       {"exclude_classes", {0, 1}},
       {"landcover_classes", {{"1", 5}, {"2", 4}, {"3", 3}, {"4", 2}, {"5", 5}, {"8", 2}}},
       {"painting_altitude", "rows"}}};
  const fs::path dir = test::temp_dir();
  const std::string store = (dir / "zion.mqt").string();
  const json report = transfer_and_assess(params, dir, store);
  ASSERT_FALSE(report.is_null());
  const Uses uses = stored_uses(store);
  const uint64_t pixels = expect_the_stored_sources(report, uses);
  std::map<int, uint64_t> by_painting;
  std::map<std::array<int, 2>, uint64_t> by_pixel;  // the painting ignored
  for (const auto& [where, n] : uses) {
    by_painting[where[0]] += n;
    by_pixel[{where[1], where[2]}] += n;
  }
  std::printf(
      "assessment: %s\n%llu of %llu pixels from The Starry Night, %zu sources (%zu "
      "columns and rows)\n",
      report.dump().c_str(), (unsigned long long)by_painting[1], (unsigned long long)pixels,
      uses.size(), by_pixel.size());
  EXPECT_EQ(by_painting.size(), 2u);
  EXPECT_GT(by_painting[1], pixels / 10);
  EXPECT_GT(by_painting[0], pixels / 10);
  EXPECT_LT(by_pixel.size(), uses.size());
  EXPECT_EQ(report.at("excluded_pixels").get<uint64_t>(), 0u);
  EXPECT_GE(report.at("label_consistency").get<double>(), kLabelGate);
}

}  // namespace
}  // namespace maquette::synthesis
