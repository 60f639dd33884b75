// StepIO's writes of a cell step's sibling cells: one batch a group, built overview and all.
#include "runtime/step_io.h"

#include <gtest/gtest.h>

#include "runtime/run_plan.h"
#include "runtime/runner.h"
#include "store/store.h"
#include "test_util.h"

namespace maquette {
namespace {

using nlohmann::json;

// The demo pipeline's blur step writing `layer`, planned on the store of a finished demo run
// (its input "height" and its output "smooth" written), with `layer` created.
struct BlurInto {
  BlurInto(const test::TempDir& dir, const std::string& layer) {
    json doc = test::demo_pipeline();
    doc["steps"] = json::array({doc["steps"][1]});
    doc["steps"][0]["outputs"]["dst"] = layer;
    pipeline = test::load_fixture_pipeline(test::write_pipeline(dir, doc));
    store = Store::open(dir.file("out.mqt"), Store::Mode::ReadWrite);
    plan = plan_run(pipeline, store.get(), 1);
    for (const auto& [port, info] : plan.steps[0].outputs) store->create_layer(info);
    run = store->begin_run(json{{"test", layer}});
  }
  // Writes `cell` with the tile the demo run stored in "smooth" there.
  void write(StepIO& io, CellId cell) const {
    const TileSet tiles{{"dst", *io.read(*store->layer("smooth"), cell)}};
    const CellOutput out{cell, &tiles};
    io.write({&out, 1});
  }
  Pipeline pipeline;
  std::unique_ptr<Store> store;
  RunPlan plan;
  int64_t run = 0;
};

TEST(StepIO, SiblingsAreWrittenInOneBatchThatBuildsTheirParentsOverview) {
  test::TempDir dir;
  RunOptions options;
  options.quiet = true;
  run_pipeline(test::load_fixture_pipeline(test::write_pipeline(dir, test::demo_pipeline())),
               options);
  const BlurInto grouped(dir, "grouped"), plain(dir, "plain");
  const std::vector<CellId>& cells = grouped.plan.steps[0].cells.cells();
  const CellId parent = cells[0].parent();
  ASSERT_EQ(cells[3].parent(), parent);
  ASSERT_NE(cells[4].parent(), parent);

  // One cell at a time, without groups: the oracle, its overview built by update_overviews.
  StepIO one_by_one(*plain.store, plain.plan.steps[0], plain.run);
  for (size_t i = 0; i < 4; ++i) plain.write(one_by_one, cells[i]);
  EXPECT_FALSE(plain.store->get_overview("plain", parent).has_value());  // stale until built
  plain.store->update_overviews("plain");
  const auto expected = plain.store->get_overview("plain", parent);
  ASSERT_TRUE(expected.has_value());

  // Grouped: the first four cells (one parent) and two of the next parent's.
  StepIO io(*grouped.store, grouped.plan.steps[0], grouped.run);
  io.group_siblings(std::span(cells).first(8));
  for (size_t i = 0; i < 3; ++i) grouped.write(io, cells[i]);
  EXPECT_FALSE(grouped.store->has_tile("grouped", cells[0]));  // held until its siblings come
  grouped.write(io, cells[3]);
  for (size_t i = 0; i < 4; ++i) EXPECT_TRUE(grouped.store->has_tile("grouped", cells[i]));
  // Written with the tiles, from the tiles in memory, and the bytes update_overviews builds.
  const auto overview = grouped.store->get_overview("grouped", parent);
  ASSERT_TRUE(overview.has_value());
  EXPECT_EQ(overview->bytes, expected->bytes);
  EXPECT_EQ(grouped.store->done_cells(grouped.run, grouped.plan.steps[0].step->index).size(), 4u);

  // A group some of whose cells never come (one failed) is written by flush().
  grouped.write(io, cells[4]);
  grouped.write(io, cells[5]);
  EXPECT_FALSE(grouped.store->has_tile("grouped", cells[4]));
  io.flush();
  EXPECT_TRUE(grouped.store->has_tile("grouped", cells[4]));
  EXPECT_TRUE(grouped.store->has_tile("grouped", cells[5]));
  EXPECT_FALSE(grouped.store->has_tile("grouped", cells[6]));
  EXPECT_FALSE(grouped.store->get_overview("grouped", cells[4].parent()).has_value());
  EXPECT_EQ(grouped.store->done_cells(grouped.run, grouped.plan.steps[0].step->index).size(), 6u);
}

}  // namespace
}  // namespace maquette
