// Coarser levels of a volume layer (content/content_overviews.h, vdb/volume_coarsen.h): the
// children's level sets merged into the parent's frame at twice the voxel size, compared with
// the same spheres made directly by OpenVDB at that voxel size; the same blobs for any order of
// cells and threads.
#include <gtest/gtest.h>
#include <openvdb/tools/Composite.h>
#include <openvdb/tools/LevelSetSphere.h>
#include <tbb/global_control.h>

#include "../store/store_test_util.h"
#include "content/content_blob.h"
#include "content/content_overviews.h"
#include "core/grid.h"
#include "lod_fixture.h"
#include "vdb/volume_vdb.h"

namespace maquette::test {
namespace {

constexpr float kRadius = 10, kVoxel = 0.5f, kHalfWidth = 3;
const openvdb::Vec3d kCentre(20, -10, 15);  // in each base cell's frame

// The four base cells under the block's first child: one sphere each.
std::vector<CellId> volume_cells() { return base_cells_under(block_cell().child(0)); }

std::string volume_blob(CellId cell) {
  auto grid = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(kRadius, kCentre, kVoxel,
                                                                       kHalfWidth);
  grid->setName("lake");
  grid->insertMeta("material", openvdb::StringMetadata("water"));
  const VolumeContent v = encode_volume({grid}, base_origin(cell));
  ContentEnvelope e;
  e.kind = ContentKind::Volume;
  e.origin = v.origin;
  e.stats = volume_stats({grid});
  return wrap_content(e, v.vdb);
}

void write_cells(Store& store, const std::vector<CellId>& cells) {
  Store::Batch batch(store);
  for (CellId cell : cells) batch.put_content("lakes", cell, volume_blob(cell));
  batch.commit();
}

openvdb::FloatGrid::Ptr read_grid(const Store& store, CellId cell, EnuOrigin& origin) {
  const std::string blob = *store.get_content("lakes", cell);
  const ContentEnvelope e = read_content_envelope(blob, cell.ToText());
  origin = e.origin;
  const auto grids = decode_volume({e.origin, std::string(content_payload(blob))}, "test");
  EXPECT_EQ(grids.size(), 1u);
  EXPECT_EQ(e.stats, volume_stats(grids));
  return openvdb::GridBase::grid<openvdb::FloatGrid>(grids.at(0));
}

TEST(VolumeLod, MergedSpheresAtTwiceTheVoxelSize) {
  TempDir dir;
  auto store = content_store(dir.file("a.mqs"), "lakes", LayerKind::Volume);
  write_cells(*store, volume_cells());
  update_content_overviews(*store, "lakes");

  CellId cell = block_cell().child(0);
  for (int level = kBaseLevel - 1; level >= kBaseLevel - 2; --level, cell = cell.parent()) {
    ASSERT_EQ(store->content_cells("lakes", level), std::vector<CellId>{cell});
    EnuOrigin origin;
    const auto got = read_grid(*store, cell, origin);
    const double voxel = kVoxel * double(1 << (kBaseLevel - level));
    EXPECT_EQ(got->getName(), "lake");
    EXPECT_EQ(got->metaValue<std::string>("material"), "water");
    EXPECT_EQ(got->getGridClass(), openvdb::GRID_LEVEL_SET);
    EXPECT_DOUBLE_EQ(got->voxelSize()[0], voxel);
    // The oracle: the four spheres made at this voxel size where they are in this frame.
    openvdb::FloatGrid::Ptr expected;
    for (CellId base : volume_cells()) {
      const auto c = reframe(base_origin(base), origin, {kCentre[0], kCentre[1], kCentre[2]});
      auto s = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(
          kRadius, openvdb::Vec3d(c[0], c[1], c[2]), float(voxel), kHalfWidth);
      if (!expected)
        expected = s;
      else
        openvdb::tools::csgUnion(*expected, *s);
    }
    const double count = double(got->activeVoxelCount());
    const double want = double(expected->activeVoxelCount());
    std::printf("level %d: %.0f active voxels, OpenVDB's spheres %.0f\n", level, count, want);
    EXPECT_NEAR(count / want, 1.0, 0.05) << "level " << level;
    const auto box = got->transform().indexToWorld(got->evalActiveVoxelBoundingBox());
    const auto want_box =
        expected->transform().indexToWorld(expected->evalActiveVoxelBoundingBox());
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(box.min()[k], want_box.min()[k], 1.01 * voxel) << "level " << level;
      EXPECT_NEAR(box.max()[k], want_box.max()[k], 1.01 * voxel) << "level " << level;
    }
    // The sphere's inside: negative at a centre, positive between spheres far from them.
    const auto c =
        reframe(base_origin(volume_cells()[0]), origin, {kCentre[0], kCentre[1], kCentre[2]});
    const openvdb::Coord centre = got->transform().worldToIndexNodeCentered({c[0], c[1], c[2]});
    EXPECT_LT(got->getConstAccessor().getValue(centre), 0);
  }
  EXPECT_EQ(store->content_stats("lakes").content.voxels,
            4 * read_content_envelope(volume_blob(volume_cells()[0]), "x").stats.voxels);
}

TEST(VolumeLod, SameBlobsForAnyOrderOfCellsAndThreads) {
  TempDir dir;
  auto a = content_store(dir.file("a.mqs"), "lakes", LayerKind::Volume);
  write_cells(*a, volume_cells());
  update_content_overviews(*a, "lakes");

  const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  auto b = content_store(dir.file("b.mqs"), "lakes", LayerKind::Volume);
  std::vector<CellId> cells = volume_cells();
  std::reverse(cells.begin(), cells.end());
  write_cells(*b, {cells.begin(), cells.begin() + 2});
  update_content_overviews(*b, "lakes");
  write_cells(*b, {cells.begin() + 2, cells.end()});
  update_content_overviews(*b, "lakes");
  const auto blobs = overview_blobs(*a, "lakes");
  EXPECT_GE(blobs.size(), 2u);
  EXPECT_TRUE(blobs == overview_blobs(*b, "lakes"));
}

}  // namespace
}  // namespace maquette::test
