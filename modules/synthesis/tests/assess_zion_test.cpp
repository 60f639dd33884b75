// synthesis.assess run by the real program after synthesis.transfer on Zion's land cover and
// DEM (../shared/data) with Bruegel's painting (8 colour classes, the sky's excluded, exemplar
// scale 4: 45,670 usable exemplar pixels for the 131,072 output pixels of 2 cells, so a
// distinct-source fraction of 0.3 is within reach: at most 0.348). The report's counts of sources
// are checked against a count of the stored source tiles, and issue 18's measures are gated at what
// the transfer meets now (README: synthesis.assess, beside the goals).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>

#include "core/tile.h"
#include "run_cli.h"
#include "store/store.h"
#include "zion_ingest.h"

namespace maquette::synthesis {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Gates at the measures of the transfer with the exemplar's measured over-use and the blocks'
// preferences (synthesis.h: D_usage, D_spread; label consistency 1, distinct sources 0.097, most
// used source 0.34 %, worst label histogram 0.328, coherence 16,237, altitude mismatch 0.179;
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

TEST(AssessZion, ReportsTheTransfersMeasuresAtTheirCurrentLevels) {
  if (!fs::exists(kPainting) || !fs::exists(kShared + "/zion/nlcd.tif"))
    GTEST_SKIP() << "../shared/data is absent";
  const fs::path dir =
      fs::temp_directory_path() / ("maquette-synthesis-assess-" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string store = (dir / "zion.mqt").string();
  json assess = transfer_params();
  assess["coherence_step"] = 4;
  json pipeline = {{"store", store},
                   {"region", {{"bbox", {-113.03, 37.25, -113.025, 37.255}}}},
                   {"level", 10},
                   {"steps",
                    {{{"op", "synthesis.transfer"},
                      {"inputs", {{"landcover", "landcover"}, {"dem", "dem"}}},
                      {"outputs", {{"rgb", "painted"}, {"source", "painted_source"}}},
                      {"params", transfer_params()}},
                     {{"op", "synthesis.assess"},
                      {"inputs",
                       {{"rgb", "painted"},
                        {"source", "painted_source"},
                        {"landcover", "landcover"},
                        {"dem", "dem"}}},
                      {"outputs", {{"report", "assessment"}}},
                      {"params", assess}}}}};
  const json ingest = zion_ingest_steps();
  pipeline["steps"].insert(pipeline["steps"].begin(), ingest.begin(), ingest.end());
  const fs::path path = dir / "pipeline.json";
  std::ofstream(path) << pipeline.dump(1);
  const test::CliResult r = test::run_maquette("run " + path.string() + " --quiet --threads 2");
  ASSERT_EQ(r.exit_code, 0) << r.err;

  const auto s = Store::open(store, Store::Mode::ReadOnly);
  const json report = json::parse(s->get_artifact("assessment")->text());
  // The sources counted again from the stored tiles: pixels, distinct ones, the most used.
  std::map<std::pair<int, int>, uint64_t> uses;
  uint64_t pixels = 0;
  for (const CellId cell : s->tile_cells("painted_source")) {
    const Tile<float> source = to_tile<float>(*s->get_tile("painted_source", cell));
    for (int row = 0; row < source.size(); ++row)
      for (int col = 0; col < source.size(); ++col)
        if (!std::isnan(source.at(col, row, 0))) {
          ++pixels;
          ++uses[{int(source.at(col, row, 0)), int(source.at(col, row, 1))}];
        }
  }
  uint64_t most = 0;
  for (const auto& [where, n] : uses) most = std::max(most, n);
  ASSERT_EQ(report.at("pixels").get<uint64_t>(), pixels);
  EXPECT_DOUBLE_EQ(report.at("distinct_source_fraction").get<double>(),
                   double(uses.size()) / double(pixels));
  EXPECT_DOUBLE_EQ(report.at("max_source_share").get<double>(), double(most) / double(pixels));
  EXPECT_GE(report.at("distinct_source_bound").get<double>(), 0.3);  // 0.3 is reachable
  // A sample of every 4th column and row, less the patches reaching beyond the region.
  EXPECT_GT(report.at("coherence_patches").get<uint64_t>(), pixels / 17);
  EXPECT_LE(report.at("coherence_patches").get<uint64_t>(), pixels / 16);

  std::printf("assessment: %s\n", report.dump().c_str());
  // Issue 18's measures at what is met now (README): the exclusion and label goals are met; the
  // others are gated at their current level so that a regression shows.
  EXPECT_EQ(report.at("excluded_pixels").get<uint64_t>(), 0u);                     // goal: 0
  EXPECT_GE(report.at("label_consistency").get<double>(), kLabelGate);             // goal: 0.97
  EXPECT_GE(report.at("distinct_source_fraction").get<double>(), kDistinctGate);   // goal: 0.3
  EXPECT_LE(report.at("max_source_share").get<double>(), kMaxShareGate);           // goal: 0.0005
  EXPECT_LE(report.at("worst_histogram_distance").get<double>(), kHistogramGate);  // goal: 0.25
  EXPECT_LE(report.at("coherence").get<double>(), kCoherenceGate);  // goal: 2 x ebsynth's
  EXPECT_LE(report.at("altitude_mismatch").get<double>(), kAltitudeGate);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace maquette::synthesis
