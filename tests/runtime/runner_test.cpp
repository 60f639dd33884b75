#include "runtime/runner.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>

#include "runtime/run_plan.h"
#include "runtime/step_io.h"
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
// must give the same bits whatever the thread count, and the threads must really run cells.
TEST(Runner, SameBitsWithOneTwoAndFourThreads) {
  test::TempDir one, two, four;
  std::map<int, size_t> threads_seen;
  for (const auto& [threads, dir] :
       {std::pair<int, test::TempDir*>{1, &one}, {2, &two}, {4, &four}}) {
    test::reset_fixture_threads();
    // The blur's cells wait for as many threads as the run has (a latch, not a timing): the
    // run passes only if that many threads really run its cells.
    json doc = demo_pipeline();
    doc["steps"][1]["params"]["meet_threads"] = threads;
    run_in(*dir, doc, threads);
    threads_seen[threads] = test::fixture_threads();
  }
  EXPECT_EQ(threads_seen[1], 1u);
  EXPECT_EQ(threads_seen[2], 2u);
  EXPECT_EQ(threads_seen[4], 4u);  // more threads than the 2 cores of a small machine
  const auto reference = test::snapshot(one.file("out.mqt"));
  // 3 layers of 64 tiles at level 4 with overviews at levels 3 to 0 (16, 4, 1, 1), one artifact.
  EXPECT_EQ(reference.size(), 3u * (64u + 16u + 4u + 1u + 1u) + 1u);
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

  const std::string file = test::write_pipeline(dir, demo_pipeline());
  const Pipeline p = test::load_fixture_pipeline(file);
  const std::string failing = p.region[20].ToText();
  EXPECT_EQ(
      error_of([&] { run_in(dir, demo_pipeline(0, 0, failing), 2); }),
      file + ": step 2 (fixture.blur) failed on cell " + failing + ": fixture failure requested");
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

// Cells 16..31 (Q21...) fail: the cell reported is the first of them whatever the thread count,
// and every cell before it is written.
TEST(Runner, ReportedFailureIsTheLowestFailingCell) {
  const json doc = demo_pipeline(0, 1, "Q21");
  for (const int threads : {1, 2, 4}) {
    SCOPED_TRACE(std::to_string(threads) + " threads");
    test::TempDir dir;
    const std::string file = test::write_pipeline(dir, doc);
    const Pipeline p = test::load_fixture_pipeline(file);
    EXPECT_EQ(error_of([&] { run_in(dir, doc, threads); }),
              file + ": step 2 (fixture.blur) failed on cell " + p.region[16].ToText() +
                  ": fixture failure requested");
    const auto written =
        Store::open(dir.file("out.mqt"), Store::Mode::ReadOnly)->tile_cells("smooth");
    EXPECT_EQ(std::vector<CellId>(written.begin(), written.begin() + 16),
              std::vector<CellId>(p.region.begin(), p.region.begin() + 16));
  }
}

TEST(Runner, OperatorThrowingANonStandardExceptionFailsTheRun) {
  test::TempDir dir;
  json doc = demo_pipeline(0, 0, "Q2013");
  doc["steps"][1]["params"]["fail_with"] = "int";
  const std::string expected = "step 2 (fixture.blur) failed on cell Q2013: unknown exception";
  // The run's record names the step; the error the pipeline file too.
  EXPECT_EQ(error_of([&] { run_in(dir, doc, 2); }), dir.file("pipeline.json") + ": " + expected);
  EXPECT_EQ(test::run_statuses(dir.file("out.mqt")),
            std::vector<std::string>{"failed: " + expected});
}

// The run's identity includes the cells a region file resolves to: after the file changes,
// --resume starts a new run instead of skipping cells of another region.
TEST(Runner, ResumeNeedsTheSameRegionCells) {
  test::TempDir dir;
  auto write_region = [&](double east) {
    std::ofstream(dir.file("region.geojson"))
        << json{{"type", "Polygon"},
                {"coordinates", {{{0, 0}, {east, 0}, {east, 10}, {0, 10}, {0, 0}}}}}
               .dump();
  };
  json doc = demo_pipeline(0, 0, "Q");  // every cell of face Q fails
  doc["region"] = {{"geojson", "region.geojson"}};
  doc["steps"] = json::array({doc["steps"][0], doc["steps"][1]});
  auto resume = [&] {
    RunOptions options;
    options.threads = 2;
    options.quiet = true;
    options.resume = true;
    error_of([&] {
      run_pipeline(test::load_fixture_pipeline(test::write_pipeline(dir, doc)), options);
    });
    return test::run_statuses(dir.file("out.mqt")).size();
  };
  write_region(10);
  EXPECT_EQ(resume(), 1u);
  EXPECT_THAT(test::run_statuses(dir.file("out.mqt"))[0], testing::StartsWith("failed: "));
  EXPECT_EQ(resume(), 1u);  // the same run, resumed
  write_region(20);
  EXPECT_EQ(resume(), 2u);  // a new run
}

// A region step's mosaic (16 x 16 cells of 4096 pixels here) is refused before anything runs.
// Run 1 fails midway through step 2; another pipeline then writes the same layers whole. Resuming
// run 1 would leave 'smooth' half of each, marked complete (an audit's find): refused, the store
// as the other pipeline left it.
TEST(Runner, ResumingARunWhoseLayerAnotherRunWroteSinceIsRefused) {
  test::TempDir dir;
  const json failing = demo_pipeline(0, 0, "Q21");
  EXPECT_NE(error_of([&] { run_in(dir, failing, 1); }), "");
  json other = demo_pipeline();
  other["steps"][1]["params"]["sleep_ms"] = 1;  // another pipeline writing the same layers
  run_in(dir, other, 2);
  const test::Snapshot before = test::snapshot(dir.file("out.mqt"));
  const std::string file = test::write_pipeline(dir, failing);
  RunOptions options;
  options.resume = true;
  options.quiet = true;
  EXPECT_EQ(error_of([&] { run_pipeline(test::load_fixture_pipeline(file), options); }),
            file +
                ": step 2 (fixture.blur): outputs.dst: layer 'smooth' was written after run 1 "
                "stopped: resuming would mix the two runs' tiles; run the pipeline without "
                "--resume");
  EXPECT_EQ(test::first_difference(before, test::snapshot(dir.file("out.mqt"))), "");
  EXPECT_FALSE(Store::open(dir.file("out.mqt"), Store::Mode::ReadOnly)->incomplete("smooth"));
}

TEST(Runner, RegionMosaicSizeIsLimited) {
  test::TempDir dir;
  json doc = demo_pipeline();
  doc["level"] = 5;
  doc["tile_size"] = 4096;
  EXPECT_EQ(
      error_of([&] { run_in(dir, doc, 2); }),
      dir.file("pipeline.json") +
          ": step 4 (fixture.region_scan): the region's mosaic would be 65536 x 65536 samples, "
          "above the limit of 16384 x 16384");
  EXPECT_FALSE(std::filesystem::exists(dir.file("out.mqt")));
}

// Each input tile of a halo step is decoded once, not once per neighbouring cell.
TEST(Runner, HaloTilesAreDecodedOnce) {
  test::TempDir dir;
  run_in(dir, demo_pipeline(), 2);
  const Pipeline p = test::load_fixture_pipeline(test::write_pipeline(dir, demo_pipeline()));
  const auto store = Store::open(dir.file("out.mqt"), Store::Mode::ReadWrite);
  const RunPlan plan = plan_run(p, store.get(), 1);
  const StepPlan& blur = plan.steps[1];
  StepIO io(*store, blur, 0);
  for (const CellId cell : blur.cells.cells()) io.load(cell, 1);
  EXPECT_EQ(io.decoded(), 64);
}

TEST(Runner, RegionOperatorNeedsOneFace) {
  test::TempDir dir;
  EXPECT_EQ(
      error_of([&] {
        run_in(dir, demo_pipeline(0, 0, "", {"Q33", "R22"}), 2);
      }),
      dir.file("pipeline.json") +
          ": step 4 (fixture.region_scan): a region operator needs all cells on one face, but they "
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
