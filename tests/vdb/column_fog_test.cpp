// columns_to_fog (vdb/column_fog.h) and its plug-in entry (maquette_vdb_column_fog): on a sheared
// lattice far from the frame's origin, exactly the columns' voxels active (found voxel by voxel
// from the columns, empty columns, columns crossing leaves and blocks filling whole leaves, which
// are tiles, included), 1, each voxel's centre
// where the lattice puts it, the provenance kept; the same bytes on any thread count and through
// the entry, and as OpenVDB's own tree of the voxels set one by one; bad input named, with the
// body.
#include "vdb/column_fog.h"

#include <gtest/gtest.h>
#include <oneapi/tbb/global_control.h>

#include <string>

#include "core/error.h"
#include "plugins/vdb_content.h"
#include "runtime/plugin.h"
#include "vdb/volume_vdb.h"
#include "vdb_fixture.h"

namespace maquette::test {
namespace {

// `width` x `height` columns of irregular extents (some empty, some crossing several leaves,
// negative and positive k) on a sheared lattice: voxels of 0.5 x 0.6 m at 30 degrees to each
// other, 0.25 m high, centred from (1203, -347.5, 41.25).
FogColumns columns(int32_t width, int32_t height) {
  FogColumns body;
  body.width = width;
  body.height = height;
  for (int32_t j = 0; j < height; ++j)
    for (int32_t i = 0; i < width; ++i) {
      // 16 x 8 columns from k = -24 to 7 whole: the regions of their 8 leaves are tiles.
      const bool deep = i < 16 && j < 8;
      body.low.push_back(deep ? -24 : -((i * 7 + j * 3) % 23) - 2);
      body.high.push_back(deep ? 8 : (i + 2 * j) % 19 - 6);
    }
  body.axes = {{{0.5, 0, 0}, {0.3, 0.6 * 0.8660254037844386, 0}, {0, 0, 0.25}}};
  body.centre = {1203, -347.5, 41.25};
  body.provenance = {77, 7, "deform.water", {}};
  body.name = "water";
  return body;
}

TEST(ColumnFog, ExactlyTheColumnsVoxelsWhereTheLatticePutsThem) {
  const FogColumns body = columns(21, 13);
  const VolumeContent volume = columns_to_fog({body}, kVolumeOrigin, "columns");
  EXPECT_EQ(volume.origin, kVolumeOrigin);
  const openvdb::GridPtrVec grids = decode_volume(volume, "columns");
  ASSERT_EQ(grids.size(), 1u);
  const auto fog = openvdb::gridPtrCast<openvdb::FloatGrid>(grids[0]);
  ASSERT_TRUE(fog);
  EXPECT_EQ(fog->getName(), "water");
  EXPECT_EQ(fog->getGridClass(), openvdb::GRID_FOG_VOLUME);
  openvdb::Index64 expected = 0;
  size_t wrong = 0, empty = 0;
  const openvdb::FloatGrid::ConstAccessor at = fog->getConstAccessor();
  for (int32_t j = -9; j < 13 + 9; ++j)
    for (int32_t i = -9; i < 21 + 9; ++i) {
      const bool inside = i >= 0 && j >= 0 && i < 21 && j < 13;
      const size_t c = size_t(j * 21 + i);
      empty += inside && body.low[c] >= body.high[c];
      for (int32_t k = -40; k < 30; ++k) {
        const bool on = inside && k >= body.low[c] && k < body.high[c];
        expected += on;
        wrong += on != at.isValueOn(openvdb::Coord(i, j, k));
      }
    }
  EXPECT_GE(empty, 5u);
  EXPECT_GT(expected, 1000u);
  EXPECT_EQ(wrong, 0u);
  EXPECT_EQ(fog->activeVoxelCount(), expected);
  EXPECT_EQ(fog->tree().activeTileCount(), 8u);
  for (auto v = fog->cbeginValueOn(); v; ++v) ASSERT_EQ(*v, 1.0f) << v.getCoord();
  // Voxel (i, j, k)'s centre: centre + i a + j b + k c.
  for (const auto& [i, j, k] : {std::array{0, 0, 0}, std::array{20, 12, -31}, {7, 3, 5}}) {
    const openvdb::Vec3d p = fog->indexToWorld(openvdb::Coord(i, j, k));
    for (size_t x = 0; x < 3; ++x)
      EXPECT_NEAR(p[x],
                  body.centre[x] + i * body.axes[0][x] + j * body.axes[1][x] + k * body.axes[2][x],
                  1e-9);
  }
  EXPECT_EQ(fog->metaValue<int64_t>("object_id"), 77);
  EXPECT_EQ(fog->metaValue<int64_t>("feature_id"), 7);
  EXPECT_EQ(fog->metaValue<std::string>("tool"), "deform.water");
}

// The same bytes as OpenVDB's own tree of the columns: each voxel set on, 1, one by one
// (Tree::setValueOn, every other value the background), pruned (a leaf all on at 1 becomes a
// tile), with the grid's transform and metadata, written by OpenVDB's own writer (io::Stream): a
// missing or extra voxel, leaf or tile, or one out of order, changes the bytes.
TEST(ColumnFog, SameBytesAsOpenVdbsTreeBuiltVoxelByVoxel) {
  const FogColumns body = columns(300, 140);  // across lower nodes (128 voxels) in x and y
  const VolumeContent volume = columns_to_fog({body}, kVolumeOrigin, "columns");
  const auto made = openvdb::gridPtrCast<openvdb::FloatGrid>(decode_volume(volume, "columns")[0]);
  ASSERT_TRUE(made);
  const openvdb::FloatGrid::Ptr oracle = openvdb::FloatGrid::create(0.0f);
  for (int32_t j = 0; j < body.height; ++j)
    for (int32_t i = 0; i < body.width; ++i) {
      const size_t c = size_t(j * body.width + i);
      for (int32_t k = body.low[c]; k < body.high[c]; ++k)
        oracle->tree().setValueOn(openvdb::Coord(i, j, k), 1.0f);
    }
  oracle->tree().prune();
  EXPECT_GE(oracle->tree().activeTileCount(), 8u);
  oracle->setTransform(made->transform().copy());
  static_cast<openvdb::MetaMap&>(*oracle) = static_cast<const openvdb::MetaMap&>(*made);
  EXPECT_EQ(compare_bytes(without_uuid(volume.vdb), openvdb_bytes({oracle})), "same");
}

// Many leaf blocks: the same bytes on one thread as on all, and through the plug-in's entry.
TEST(ColumnFog, SameBytesForAnyThreadCountAndThroughThePlugin) {
  const FogColumns body = columns(400, 300);
  const VolumeContent all = columns_to_fog({body, columns(9, 5)}, kVolumeOrigin, "columns");
  {
    const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
    EXPECT_EQ(columns_to_fog({body, columns(9, 5)}, kVolumeOrigin, "columns").vdb, all.vdb);
  }
  {
    const tbb::global_control two_threads(tbb::global_control::max_allowed_parallelism, 2);
    EXPECT_EQ(columns_to_fog({body, columns(9, 5)}, kVolumeOrigin, "columns").vdb, all.vdb);
  }
  auto* entry = plugin_function<decltype(maquette_vdb_column_fog)>(kVdbPlugin, kVdbColumnFogEntry);
  VolumeContent through;
  entry({body, columns(9, 5)}, kVolumeOrigin, "columns", through);
  EXPECT_EQ(through.vdb, all.vdb);
  EXPECT_EQ(decode_volume(all, "columns").size(), 2u);
}

TEST(ColumnFog, BadBodiesAreNamed) {
  auto* entry = plugin_function<decltype(maquette_vdb_column_fog)>(kVdbPlugin, kVdbColumnFogEntry);
  FogColumns short_lows = columns(4, 3);
  short_lows.low.pop_back();
  FogColumns flat = columns(4, 3);
  flat.axes[1] = {1.0, 0, 0};  // along axes[0]: no area
  FogColumns far = columns(4, 3);
  far.high[5] = (1 << 30) + 1;
  FogColumns nan_centre = columns(4, 3);
  nan_centre.centre[2] = NAN;
  for (const auto& [body, says] :
       {std::pair{short_lows, "11 lows and 12 highs for 4 x 3 columns"},
        std::pair{flat, "the lattice's axes do not span space"},
        std::pair{far, "column 5 holds voxels"}, std::pair{nan_centre, "centre is not finite"}})
    try {
      VolumeContent volume;
      entry({columns(2, 2), body}, kVolumeOrigin, "deform.water, cell N3021", volume);
      ADD_FAILURE() << says << ": accepted";
    } catch (const Error& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("deform.water, cell N3021, body 1: "), std::string::npos) << what;
      EXPECT_NE(what.find(says), std::string::npos) << what;
    }
}

}  // namespace
}  // namespace maquette::test
