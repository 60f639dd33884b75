// The stream writer (formats/vdb/vdb_stream_writer.h) against OpenVDB's own io::Stream: the same
// bytes, its random UUID aside, for grids covering every kind of leaf it writes and the grids it
// leaves to OpenVDB.
#include "vdb/vdb_stream_writer.h"

#include <gtest/gtest.h>
#include <oneapi/tbb/global_control.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "core/error.h"
#include "vdb/volume_vdb.h"
#include "vdb_fixture.h"

namespace maquette::test {
namespace {

std::string writer_bytes(const openvdb::GridPtrVec& grids) {
  return without_uuid(write_vdb_stream(grids));
}

// A fog box whose full leaves (x from -16 to 23 in leaves of 8, y 0 to 7, z -8 to 23) hold each
// kind of inactive values OpenVDB's mask compression tells apart (one other than the background,
// two others, the background and one other, more: all values written) and random bits (Blosc
// keeps them uncompressed in its frame); its partial leaves have the background only, inactive.
openvdb::FloatGrid::Ptr mixed_fog() {
  auto grid = fog_box(openvdb::CoordBBox({-20, -4, -9}, {27, 11, 30}), 0.5, "mixed");
  auto access = grid->getAccessor();
  access.setValueOff({-16, 0, 0}, 0.25f);
  access.setValueOff({-8, 0, 0}, 0.25f);
  access.setValueOff({-8, 0, 1}, 0.5f);
  access.setValueOff({0, 0, 0}, 0.25f);
  access.setValueOff({0, 0, 1}, 0.0f);
  for (int k = 8; k < 16; ++k) access.setValueOff({8, 0, k}, float(k));
  std::mt19937 random(5);
  for (int i = 16; i < 24; ++i)
    for (int j = 0; j < 8; ++j)
      for (int k = 16; k < 24; ++k) {
        const uint32_t bits = uint32_t(random()) & 0xBF7FFFFFu;  // finite
        float value;
        std::memcpy(&value, &bits, sizeof value);
        access.setValueOn({i, j, k}, value);
      }
  return grid;
}

TEST(VdbStreamWriter, SameBytesAsOpenVdbsWriter) {
  auto sphere = sphere_level_set("lake");
  sphere->insertMeta("tool", openvdb::StringMetadata("deform.water"));
  const auto fog = mixed_fog();
  auto half = fog_box(openvdb::CoordBBox({0, 0, 0}, {9, 9, 9}), 1, "half");
  half->setSaveFloatAsHalf(true);               // written by OpenVDB
  auto vectors = openvdb::Vec3SGrid::create();  // written by OpenVDB
  vectors->fill(openvdb::CoordBBox({0, 0, 0}, {9, 3, 3}), openvdb::Vec3s(1, 2, 3));
  auto empty = openvdb::FloatGrid::create(0.0f);  // no leaves: empty delayed-load metadata
  // A NaN background: OpenVDB's mask compression finds no inactive value equal to it.
  auto nan = openvdb::FloatGrid::create(std::numeric_limits<float>::quiet_NaN());
  nan->fill(openvdb::CoordBBox({0, 0, 0}, {9, 3, 3}), 1.0f);
  const auto shared = openvdb::FloatGrid::create(fog->treePtr());  // an instance of fog's tree
  shared->setName("mixed");
  const openvdb::GridPtrVec grids{sphere, fog, half, vectors, empty, nan, shared};
  const std::string expected = openvdb_bytes(grids);
  ASSERT_GT(expected.size(), 100000u);
  EXPECT_EQ(compare_bytes(writer_bytes(grids), expected), "same");
  const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  EXPECT_EQ(compare_bytes(writer_bytes(grids), expected), "same");
}

// The bytes of a lake's many leaves and tiles (columns_to_fog's), and one leaf alone.
TEST(VdbStreamWriter, SameBytesForManyLeavesAndForOne) {
  auto terraces = openvdb::FloatGrid::create(0.0f);
  terraces->setGridClass(openvdb::GRID_FOG_VOLUME);
  for (int i = -300; i < 300; i += 7)
    for (int j = -200; j < 200; j += 5)
      terraces->fill(openvdb::CoordBBox({i, j, -(i * i + j * j) % 37}, {i + 6, j + 4, 0}), 1.0f);
  const openvdb::GridPtrVec many{terraces};
  EXPECT_GT(terraces->tree().leafCount(), 2000u);
  EXPECT_EQ(compare_bytes(writer_bytes(many), openvdb_bytes(many)), "same");
  const openvdb::GridPtrVec one{fog_box(openvdb::CoordBBox({1, 1, 1}, {2, 2, 2}), 1, "one")};
  EXPECT_EQ(compare_bytes(writer_bytes(one), openvdb_bytes(one)), "same");
}

// Fog trees (FogGrid) against OpenVDB's writer of the trees they stand for, built by OpenVDB's own
// calls (Tree::addLeaf, Tree::addTile): leaves across root children on every axis (negative
// coordinates too), many in one lower node, masks of one voxel, of random voxels and of all 512,
// active tiles beside leaves and alone; given out of order (sort_in_tree_order puts them in
// order). Two grids, one of them without leaves or tiles.
TEST(VdbStreamWriter, FogTreesSameBytesAsOpenVdbsTreesAndWriter) {
  std::mt19937 random(11);
  const openvdb::FloatGrid::Ptr lake = fog_box(openvdb::CoordBBox(), 0.5, "lake");
  lake->insertMeta("tool", openvdb::StringMetadata("deform.water"));
  FogGrid fog{lake, {}};
  const openvdb::FloatGrid::Ptr oracle = openvdb::FloatGrid::create(kFogBackground);
  std::set<openvdb::Coord> used;
  std::vector<openvdb::Coord> origins;
  const auto draw = [&] { return (int(random() % 1200) - 600) * 8; };
  for (int n = 0; n < 600; ++n) {  // +-4800 voxels: 3 or 4 root children on each axis
    const int x = draw(), y = draw();
    origins.emplace_back(x, y, draw());
  }
  for (int x = -24; x <= 8; x += 8)
    for (int y = -24; y <= 8; y += 8)
      for (int z = -24; z <= 8; z += 8) origins.emplace_back(x, y, z);
  std::shuffle(origins.begin(), origins.end(), random);
  for (size_t n = 0; n < origins.size(); ++n) {
    const openvdb::Coord origin = origins[n];
    if (!used.insert(origin).second) continue;
    if (n % 9 == 4) {
      fog.tree.tiles.push_back(origin);
      oracle->tree().addTile(1, origin, kFogDensity, /*active=*/true);
      continue;
    }
    FogLeaf leaf{origin};
    for (uint64_t& word : leaf.mask) {
      const uint64_t high = uint64_t(random()), low = uint64_t(random());  // in this order
      word = n % 7 == 0 ? ~uint64_t(0) : n % 7 == 1 ? 0 : high << 32 | low;
    }
    if (n % 7 == 1) leaf.mask[n % 8] = uint64_t(1) << (n % 64);
    fog.tree.leaves.push_back(leaf);
    auto* node = new openvdb::FloatTree::LeafNodeType(origin, kFogBackground);
    for (openvdb::Index v = 0; v < node->SIZE; ++v)
      if (leaf.mask[v / 64] >> (v % 64) & 1) node->setValueOn(v, kFogDensity);
    oracle->tree().addLeaf(node);
  }
  ASSERT_GT(fog.tree.leaves.size(), 500u);
  ASSERT_GT(fog.tree.tiles.size(), 50u);
  sort_in_tree_order(fog.tree);
  oracle->setTransform(fog.grid->transform().copy());
  static_cast<openvdb::MetaMap&>(*oracle) = static_cast<const openvdb::MetaMap&>(*fog.grid);
  const FogGrid empty{fog_box(openvdb::CoordBBox(), 1, "empty"), {}};
  const openvdb::FloatGrid::Ptr empty_oracle = empty.grid->deepCopy();
  const std::string expected = openvdb_bytes({oracle, empty_oracle});
  EXPECT_EQ(compare_bytes(without_uuid(write_vdb_stream({fog, empty})), expected), "same");
  const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  EXPECT_EQ(compare_bytes(without_uuid(write_vdb_stream({fog, empty})), expected), "same");
}

// A fog tree out of tree order, or with an origin twice, is refused naming the place, not
// written as a corrupt stream.
TEST(VdbStreamWriter, FogTreesOutOfOrderAreRefused) {
  const auto grid = fog_box(openvdb::CoordBBox(), 1, "unordered");
  FogLeaf a{openvdb::Coord(0, 0, 0)}, b{openvdb::Coord(8, 0, 0)};
  a.mask[0] = b.mask[0] = 1;
  const auto error_of = [&](std::vector<FogLeaf> leaves) -> std::string {
    try {
      write_vdb_stream({FogGrid{grid, FogTree{std::move(leaves), {}}}});
    } catch (const Error& e) {
      return e.what();
    }
    return "written";
  };
  EXPECT_EQ(error_of({a, b}), "written");
  EXPECT_NE(error_of({b, a}).find("not in tree order or hold an origin twice"), std::string::npos)
      << error_of({b, a});
  EXPECT_NE(error_of({a, a}).find("(in the upper node at 0, 0, 0, lower 0, leaf 0)"),
            std::string::npos)
      << error_of({a, a});
}

}  // namespace
}  // namespace maquette::test
