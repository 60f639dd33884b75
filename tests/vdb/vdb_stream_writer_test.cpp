// The stream writer (formats/vdb/vdb_stream_writer.h) against OpenVDB's own io::Stream: the same
// bytes, its random UUID aside, for grids covering every kind of leaf it writes and the grids it
// leaves to OpenVDB.
#include "vdb/vdb_stream_writer.h"

#include <gtest/gtest.h>
#include <oneapi/tbb/global_control.h>
#include <openvdb/io/Stream.h>

#include <cstring>
#include <limits>
#include <random>
#include <sstream>

#include "vdb/volume_vdb.h"
#include "vdb_fixture.h"

namespace maquette::test {
namespace {

// OpenVDB's writer with encode_volume's options, its UUID blanked.
std::string openvdb_bytes(const openvdb::GridPtrVec& grids) {
  std::ostringstream out(std::ios::binary);
  openvdb::io::Stream stream(out);
  stream.setCompression(openvdb::io::COMPRESS_BLOSC | openvdb::io::COMPRESS_ACTIVE_MASK);
  stream.setGridStatsMetadataEnabled(false);
  stream.write(grids);
  return std::move(out).str().replace(kVdbUuidOffset, kVdbUuidBytes, kVdbUuidBytes, '-');
}

std::string writer_bytes(const openvdb::GridPtrVec& grids) {
  return write_vdb_stream(grids).replace(kVdbUuidOffset, kVdbUuidBytes, kVdbUuidBytes, '-');
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

}  // namespace
}  // namespace maquette::test
