// Volumes as VDB streams (formats/vdb/volume_vdb.h): deterministic bytes, bit-exact round trips,
// bad payloads named, statistics.
#include "vdb/volume_vdb.h"

#include <gtest/gtest.h>
#include <oneapi/tbb/global_control.h>

#include <algorithm>
#include <boost/uuid/name_generator_sha1.hpp>
#include <boost/uuid/nil_generator.hpp>
#include <boost/uuid/uuid_io.hpp>
#include <cstring>

#include "core/error.h"
#include "vdb_fixture.h"

namespace maquette::test {
namespace {

openvdb::GridPtrVec two_grids() {
  auto sphere = sphere_level_set("lake");
  sphere->insertMeta("tool", openvdb::StringMetadata("deform.water"));
  sphere->insertMeta("feature_id", openvdb::Int64Metadata(42));
  return {sphere, fog_box(openvdb::CoordBBox({-3, 2, 0}, {12, 9, 4}), 0.5, "cloud")};
}

uint32_t bits(float value) {
  uint32_t b;
  std::memcpy(&b, &value, sizeof b);
  return b;
}

// Every value of the two trees, voxels and tiles, active or not, compared bit for bit, with the
// active states, the topology and the background.
void expect_same_tree(const openvdb::FloatTree& a, const openvdb::FloatTree& b) {
  ASSERT_TRUE(a.hasSameTopology(b));
  EXPECT_EQ(bits(a.background()), bits(b.background()));
  auto i = a.cbeginValueAll();
  auto j = b.cbeginValueAll();
  size_t values = 0;
  for (; i && j; ++i, ++j, ++values) {
    ASSERT_EQ(i.getCoord(), j.getCoord());
    ASSERT_EQ(i.getDepth(), j.getDepth());
    ASSERT_EQ(i.isValueOn(), j.isValueOn()) << i.getCoord();
    ASSERT_EQ(bits(*i), bits(*j)) << i.getCoord();
  }
  EXPECT_FALSE(i);
  EXPECT_FALSE(j);
  EXPECT_GT(values, a.activeVoxelCount());
}

TEST(VolumeVdb, SameGridsSameBytes) {
  const auto grids = two_grids();
  const VolumeContent first = encode_volume(grids, kVolumeOrigin);
  const VolumeContent second = encode_volume(grids, kVolumeOrigin);
  EXPECT_EQ(first.origin, kVolumeOrigin);
  ASSERT_GT(first.vdb.size(), 10000u);
  EXPECT_EQ(compare_bytes(first.vdb, second.vdb), "same");
  // Rebuilt grids (other trees, other addresses) and a single writer thread: the same bytes.
  {
    const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
    EXPECT_EQ(compare_bytes(encode_volume(two_grids(), kVolumeOrigin).vdb, first.vdb), "same");
  }
  // Decoded and encoded again: the same bytes (nothing of the writer's process is in them).
  EXPECT_EQ(
      compare_bytes(encode_volume(decode_volume(first, "test"), kVolumeOrigin).vdb, first.vdb),
      "same");
}

TEST(VolumeVdb, UuidIsDerivedFromTheContent) {
  const std::string a = encode_volume(two_grids(), kVolumeOrigin).vdb;
  const std::string b = encode_volume({sphere_level_set("lake")}, kVolumeOrigin).vdb;
  const std::string uuid = a.substr(kVdbUuidOffset, kVdbUuidBytes);
  // 8-4-4-4-12 hex digits, version 5 (name-based, SHA-1), RFC 4122 variant.
  ASSERT_EQ(uuid.size(), 36u);
  for (size_t k : {8u, 13u, 18u, 23u}) EXPECT_EQ(uuid[k], '-') << uuid;
  EXPECT_EQ(uuid[14], '5') << uuid;
  EXPECT_NE(std::string("89ab").find(uuid[19]), std::string::npos) << uuid;
  EXPECT_NE(b.substr(kVdbUuidOffset, kVdbUuidBytes), uuid);
  // The rest of the header is OpenVDB's: the magic number and the file format version 224.
  EXPECT_EQ(a.substr(0, 4), std::string(" BDV"));
  uint32_t format = 0;
  std::memcpy(&format, a.data() + 8, 4);
  EXPECT_GE(format, 224u);
}

TEST(VolumeVdb, RoundTripIsBitExact) {
  const auto grids = two_grids();
  const auto decoded =
      decode_volume(encode_volume(grids, kVolumeOrigin), "layer lakes, cell N3021");
  ASSERT_EQ(decoded.size(), grids.size());
  for (size_t g = 0; g < grids.size(); ++g) {
    SCOPED_TRACE(grids[g]->getName());
    const auto a = openvdb::gridPtrCast<openvdb::FloatGrid>(grids[g]);
    const auto b = openvdb::gridPtrCast<openvdb::FloatGrid>(decoded[g]);
    ASSERT_TRUE(b);
    EXPECT_EQ(b->getName(), a->getName());
    EXPECT_EQ(b->getGridClass(), a->getGridClass());
    EXPECT_EQ(b->transform(), a->transform());
    EXPECT_EQ(b->str(), a->str());  // metadata, as text
    expect_same_tree(a->tree(), b->tree());
  }
  const auto sphere = openvdb::gridPtrCast<openvdb::FloatGrid>(decoded[0]);
  EXPECT_EQ(sphere->metaValue<std::string>("tool"), "deform.water");
  EXPECT_EQ(sphere->metaValue<int64_t>("feature_id"), 42);
  EXPECT_EQ(sphere->voxelSize(), openvdb::Vec3d(kSphereVoxel));
}

TEST(VolumeVdb, BadPayloadsAreNamed) {
  const VolumeContent good = encode_volume(two_grids(), kVolumeOrigin);
  const std::string where = "layer lakes, cell N3021";
  const auto refused = [&](const std::string& vdb, const std::string& why) {
    try {
      decode_volume(VolumeContent{kVolumeOrigin, vdb}, where);
      ADD_FAILURE() << why << ": decoded";
    } catch (const Error& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind(where + ": the volume is not a whole VDB stream", 0), 0u)
          << why << ": " << message;
    }
  };
  refused("", "empty");
  refused("this is a JPEG, not a VDB stream, honest", "not a VDB");
  refused(good.vdb.substr(0, good.vdb.size() / 2), "truncated in the middle");
  refused(good.vdb.substr(0, good.vdb.size() - 1), "truncated by one byte");
  refused(good.vdb.substr(0, 40), "truncated in the header");
  refused(good.vdb + "trailing", "trailing bytes");
  refused(std::string(good.vdb).replace(kVdbUuidOffset, 1, "0"), "another UUID");
  std::string bad_magic = good.vdb;
  bad_magic[1] = 'X';
  refused(bad_magic, "bad magic");
}

TEST(VolumeVdb, AnyChangedByteIsRefused) {
  const VolumeContent good = encode_volume(two_grids(), kVolumeOrigin);
  // Most of these OpenVDB alone would read as other values (31 of 98 refused, measured).
  for (size_t at = 0; at < good.vdb.size(); at += good.vdb.size() / 97) {
    VolumeContent bad = good;
    bad.vdb[at] ^= 0x20;
    EXPECT_THROW(decode_volume(bad, "cell"), Error) << "byte " << at;
  }
}

// A stream given the UUID encode_volume would give it (UuidIsDerivedFromTheContent checks the
// format), so that what OpenVDB reads of it is checked too.
std::string resealed(std::string vdb) {
  std::string name = vdb.substr(0, kVdbUuidOffset) + vdb.substr(kVdbUuidOffset + kVdbUuidBytes);
  const boost::uuids::name_generator_sha1 generate(boost::uuids::nil_uuid());
  return vdb.replace(kVdbUuidOffset, kVdbUuidBytes,
                     boost::uuids::to_string(generate(name.data(), name.size())));
}

TEST(VolumeVdb, MalformedStreamsWithTheirUuidAreRefused) {
  const std::string good = encode_volume(two_grids(), kVolumeOrigin).vdb;
  EXPECT_NO_THROW(decode_volume(VolumeContent{kVolumeOrigin, resealed(good)}, "cell"));
  const auto refused = [&](const std::string& vdb, const std::string& why) {
    try {
      decode_volume(VolumeContent{kVolumeOrigin, resealed(vdb)}, "layer lakes, cell N3021");
      ADD_FAILURE() << why << ": decoded";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
    }
  };
  refused(good + "trailing", "8 bytes after its last grid");
  refused(good.substr(0, good.size() - 1), "truncated");
  refused(good.substr(0, good.size() - 100), "RuntimeError: Expected to decompress");
  std::string unknown_type = good;
  const size_t type = unknown_type.find("Tree_float_5_4_3");
  ASSERT_NE(type, std::string::npos);
  unknown_type.replace(type, 16, "Tree_flaot_5_4_3");
  refused(unknown_type, "Tree_flaot_5_4_3");
}

TEST(VolumeVdb, NullGridIsRefused) {
  EXPECT_THROW(encode_volume({sphere_level_set("a"), nullptr}, kVolumeOrigin), Error);
}

TEST(VolumeVdb, StatsCountGridsAndActiveVoxels) {
  // A 16 x 8 x 5 box: 640 active voxels, whatever tiles fill() made of them.
  const auto box = fog_box(openvdb::CoordBBox({-3, 2, 0}, {12, 9, 4}), 0.5, "cloud");
  const auto sphere = sphere_level_set("lake");
  // The sphere's narrow band counted voxel by voxel (it has no active tiles).
  uint64_t band = 0;
  for (auto leaf = sphere->tree().cbeginLeaf(); leaf; ++leaf)
    band += leaf->getValueMask().countOn();
  const ContentStats stats =
      volume_stats(decode_volume(encode_volume({box, sphere}, kVolumeOrigin), "t"));
  EXPECT_EQ(stats.objects, 2u);
  EXPECT_EQ(stats.triangles, 0u);
  EXPECT_EQ(stats.voxels, 640u + band);
  // The band is about six voxels thick (three either side) over the sphere's area.
  const double shell = 4 * M_PI * kSphereRadius * kSphereRadius * 6 * kSphereVoxel;
  EXPECT_NEAR(double(band) * std::pow(kSphereVoxel, 3), shell, 0.1 * shell);
}

}  // namespace
}  // namespace maquette::test
