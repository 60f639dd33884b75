#include "runtime/runner.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "store/store.h"
#include "test_util.h"

namespace maquette {
namespace {

using nlohmann::json;
using test::demo_pipeline;
using test::error_of;

RunSummary run_in(const test::TempDir& dir, const json& doc, int threads) {
  RunOptions options;
  options.threads = threads;
  options.quiet = true;
  return run_pipeline(test::load_fixture_pipeline(test::write_pipeline(dir, doc)), options);
}

TEST(Runner, WritesEveryLayerAndArtifact) {
  test::TempDir dir;
  const RunSummary summary = run_in(dir, demo_pipeline(), 2);
  ASSERT_EQ(summary.steps.size(), 4u);
  for (const auto& s : summary.steps) {
    EXPECT_EQ(s.cells, 64);
    EXPECT_EQ(s.computed, 64);
  }
  const auto store = Store::open(dir.file("out.mqt"), Store::Mode::ReadOnly);
  for (const char* layer : {"height", "smooth", "scan"})
    EXPECT_EQ(store->tile_cells(layer).size(), 64u) << layer;
  const LayerInfo smooth = store->require_layer("smooth");
  EXPECT_EQ(smooth.level, 4);
  EXPECT_EQ(smooth.tile_size, 16);
  EXPECT_EQ(smooth.nodata, -9999);
  EXPECT_EQ(smooth.provenance.at("operator"), "fixture.blur");
  const auto total = json::parse(store->get_artifact("smooth_sum")->data);
  EXPECT_EQ(total.at("count"), 64 * 16 * 16);
  EXPECT_TRUE(store->get_overview("smooth", CellId::FromText("Q2").value()).has_value());
}

// The blur reads neighbours through the halo and the float sum depends on merge order: both
// must give the same bits whatever the thread count.
TEST(Runner, SameBitsWithOneTwoAndFourThreads) {
  test::TempDir one, two, four;
  run_in(one, demo_pipeline(), 1);
  run_in(two, demo_pipeline(), 2);
  run_in(four, demo_pipeline(), 4);
  const auto reference = test::snapshot(one.file("out.mqt"));
  EXPECT_EQ(reference.size(), 3u * 64u + 1u);
  EXPECT_EQ(test::first_difference(reference, test::snapshot(two.file("out.mqt"))), "");
  EXPECT_EQ(test::first_difference(reference, test::snapshot(four.file("out.mqt"))), "");
}

TEST(Runner, RerunIsIdempotent) {
  test::TempDir dir;
  run_in(dir, demo_pipeline(), 2);
  const auto before = test::snapshot(dir.file("out.mqt"));
  const RunSummary again = run_in(dir, demo_pipeline(), 3);
  EXPECT_FALSE(again.resumed);
  EXPECT_EQ(again.steps[1].computed, 64);
  EXPECT_EQ(test::first_difference(before, test::snapshot(dir.file("out.mqt"))), "");
}

TEST(Runner, FailingOperatorNamesStepAndCellAndKeepsEarlierTiles) {
  test::TempDir dir;
  run_in(dir, demo_pipeline(), 2);
  const auto before = test::snapshot(dir.file("out.mqt"));

  const Pipeline p = test::load_fixture_pipeline(test::write_pipeline(dir, demo_pipeline()));
  const std::string failing = p.region[20].ToText();
  EXPECT_EQ(error_of([&] { run_in(dir, demo_pipeline(0, 0, failing), 2); }),
            "step 2 (fixture.blur) failed on cell " + failing + ": fixture failure requested");
  // Cells written before the failure were rewritten with the same bits, the others untouched.
  EXPECT_EQ(test::first_difference(before, test::snapshot(dir.file("out.mqt"))), "");

  // In a fresh store with one thread, exactly the cells before the failing one are written.
  test::TempDir fresh;
  EXPECT_NE(error_of([&] { run_in(fresh, demo_pipeline(0, 0, failing), 1); }), "");
  const auto store = Store::open(fresh.file("out.mqt"), Store::Mode::ReadOnly);
  const auto written = store->tile_cells("smooth");
  EXPECT_EQ(written, std::vector<CellId>(p.region.begin(), p.region.begin() + 20));
  for (const CellId c : written)
    EXPECT_EQ(store->get_tile("smooth", c)->bytes, before.at("smooth/" + c.ToText()));
  EXPECT_FALSE(store->get_artifact("smooth_sum").has_value());
}

TEST(Runner, RegionOperatorNeedsOneFace) {
  test::TempDir dir;
  EXPECT_EQ(error_of([&] {
              run_in(dir, demo_pipeline(0, 0, "", {"Q33", "R22"}), 2);
            }),
            "step 4 (fixture.region_scan): a region operator needs all cells on one face, but they "
            "span faces Q to R");
}

TEST(Runner, StepsReadTilesOfTheRegionOnly) {
  test::TempDir dir;
  run_in(dir, demo_pipeline(), 2);
  // A second pipeline on part of the region reads only the stored tiles inside it.
  json doc = demo_pipeline(0, 0, "", {"Q21"});
  doc["steps"] = json::array({doc["steps"][1]});
  doc["steps"][0]["outputs"]["dst"] = "smooth_part";
  const RunSummary summary = run_in(dir, doc, 2);
  EXPECT_EQ(summary.steps[0].cells, 16);
}

}  // namespace
}  // namespace maquette
