// mesh_to_fog (vdb/mesh_fog.h) and its plug-in entry (maquette_vdb_mesh_fog) on a closed box
// whose faces lie on the voxel lattice's faces: exactly the box's voxels active (its volume to
// the last bit), 1 inside; a box whose faces cut voxels: the voxels whose centres are inside,
// found from the box's own equations (through the function and through the entry); the
// provenance kept; the same bytes on any thread count (a sphere of many triangles); bad input
// named, a body beyond the grid's 32-bit coordinates refused.
#include "vdb/mesh_fog.h"

#include <gtest/gtest.h>
#include <oneapi/tbb/global_control.h>

#include <cmath>
#include <string>
#include <tuple>

#include "core/error.h"
#include "plugins/vdb_content.h"
#include "runtime/plugin.h"
#include "vdb/volume_vdb.h"
#include "vdb_fixture.h"

namespace maquette::test {
namespace {

// A box [x0, x0 + 10] x [y0, y0 + 6] x [z0, z0 + 4] (metres) far from the frame's origin, as a
// closed mesh, counter-clockwise seen from outside, with voxels of 0.5 x 0.5 x 0.25 m whose
// lattice has a corner at the box's; turned by `angle` (radians) about the vertical through
// (x0, y0).
constexpr double kX0 = 1203, kY0 = -347.5, kZ0 = 41.25;
FogBody box_body(double angle = 0) {
  FogBody body;
  const double c = std::cos(angle), s = std::sin(angle);
  for (int k = 0; k < 8; ++k) {
    const double x = 10 * (k & 1), y = 6 * ((k >> 1) & 1);
    body.mesh.positions.insert(
        body.mesh.positions.end(),
        {float(kX0 + c * x - s * y), float(kY0 + s * x + c * y), float(kZ0 + 4 * (k >> 2))});
  }
  body.mesh.indices = {0, 2, 3, 0, 3, 1,   // bottom (z0), facing down
                       4, 5, 7, 4, 7, 6,   // top
                       0, 1, 5, 0, 5, 4,   // y0
                       2, 6, 7, 2, 7, 3,   // y0 + 6
                       0, 4, 6, 0, 6, 2,   // x0
                       1, 3, 7, 1, 7, 5};  // x0 + 10
  body.mesh.provenance = {77, 7, "deform.water", {}};
  body.voxel = {0.5, 0.5, 0.25};
  body.corner = {kX0, kY0, kZ0};
  body.name = "water";
  return body;
}

TEST(MeshFog, BoxOnTheLatticeGivesExactlyItsVoxels) {
  const VolumeContent volume = mesh_to_fog({box_body()}, kVolumeOrigin, "box");
  EXPECT_EQ(volume.origin, kVolumeOrigin);
  const openvdb::GridPtrVec grids = decode_volume(volume, "box");
  ASSERT_EQ(grids.size(), 1u);
  const auto fog = openvdb::gridPtrCast<openvdb::FloatGrid>(grids[0]);
  ASSERT_TRUE(fog);
  EXPECT_EQ(fog->getName(), "water");
  EXPECT_EQ(fog->getGridClass(), openvdb::GRID_FOG_VOLUME);
  EXPECT_EQ(fog->activeVoxelCount(), openvdb::Index64(20 * 12 * 16));
  const openvdb::CoordBBox box = fog->evalActiveVoxelBoundingBox();
  const openvdb::Vec3d lo = fog->indexToWorld(box.min()), hi = fog->indexToWorld(box.max());
  EXPECT_NEAR(lo[0], kX0 + 0.25, 1e-9);
  EXPECT_NEAR(hi[0], kX0 + 10 - 0.25, 1e-9);
  EXPECT_NEAR(lo[1], kY0 + 0.25, 1e-9);
  EXPECT_NEAR(hi[1], kY0 + 6 - 0.25, 1e-9);
  EXPECT_NEAR(lo[2], kZ0 + 0.125, 1e-9);
  EXPECT_NEAR(hi[2], kZ0 + 4 - 0.125, 1e-9);
  for (auto v = fog->cbeginValueOn(); v; ++v) ASSERT_EQ(*v, 1.0f) << v.getCoord();
  EXPECT_EQ(fog->metaValue<int64_t>("object_id"), 77);
  EXPECT_EQ(fog->metaValue<int64_t>("feature_id"), 7);
  EXPECT_EQ(fog->metaValue<std::string>("tool"), "deform.water");
}

// The box of box_body(angle) turned by 0.5 rad, its lattice shifted.
FogBody turned_box() {
  FogBody body = box_body(0.5);
  body.corner = {kX0 + 0.1, kY0 + 0.2, kZ0 + 0.05};
  return body;
}

// The active voxels of `grid` are those whose centres lie in the box of box_body(angle), found
// from the box's own equations.
void expect_the_box_s_voxels(const openvdb::GridBase::Ptr& grid, double angle) {
  const auto fog = openvdb::gridPtrCast<openvdb::FloatGrid>(grid);
  ASSERT_TRUE(fog);
  const double c = std::cos(angle), s = std::sin(angle);
  openvdb::Index64 inside = 0;
  size_t wrong = 0;
  const openvdb::FloatGrid::ConstAccessor at = fog->getConstAccessor();
  for (int i = -40; i < 40; ++i)
    for (int j = -10; j < 60; ++j)
      for (int k = -2; k < 20; ++k) {
        const openvdb::Vec3d p = fog->indexToWorld(openvdb::Coord(i, j, k));
        const double u = c * (p[0] - kX0) + s * (p[1] - kY0);
        const double v = -s * (p[0] - kX0) + c * (p[1] - kY0);
        const bool in = u > 0 && u < 10 && v > 0 && v < 6 && p[2] > kZ0 && p[2] < kZ0 + 4;
        inside += in;
        wrong += in != at.isValueOn(openvdb::Coord(i, j, k));
      }
  EXPECT_GT(inside, 3000u);
  EXPECT_EQ(wrong, 0u) << "of " << inside << " voxels inside";
  EXPECT_EQ(fog->activeVoxelCount(), inside);
  for (auto v = fog->cbeginValueOn(); v; ++v) ASSERT_EQ(*v, 1.0f) << v.getCoord();
}

TEST(MeshFog, TurnedBoxGivesTheVoxelsWhoseCentresAreInside) {
  const openvdb::GridPtrVec grids =
      decode_volume(mesh_to_fog({turned_box()}, kVolumeOrigin, "box"), "box");
  ASSERT_EQ(grids.size(), 1u);
  expect_the_box_s_voxels(grids[0], 0.5);
}

// A closed sphere of radius 5 m centred at (kX0, kY0, kZ0): `rings` rings of latitude, `segments`
// of longitude, fans at the poles, counter-clockwise seen from outside; voxels of 0.1 m.
FogBody sphere_body(int rings, int segments) {
  FogBody body;
  body.mesh.positions.reserve(3 * size_t((rings - 1) * segments + 2));
  const auto add = [&](double theta, double phi) {
    body.mesh.positions.insert(
        body.mesh.positions.end(),
        {float(kX0 + 5 * std::sin(theta) * std::cos(phi)),
         float(kY0 + 5 * std::sin(theta) * std::sin(phi)), float(kZ0 + 5 * std::cos(theta))});
  };
  add(0, 0);  // vertex 0: the north pole; 1 + (i - 1) * segments + j: ring i, segment j
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < segments; ++j) add(M_PI * i / rings, 2 * M_PI * j / segments);
  add(M_PI, 0);  // the south pole
  const uint32_t south = uint32_t(body.mesh.positions.size() / 3 - 1);
  const auto vertex = [&](int i, int j) {
    return i == 0 ? 0u : i == rings ? south : uint32_t(1 + (i - 1) * segments + j % segments);
  };
  // Quad (i, j) (i + 1, j) (i + 1, j + 1) (i, j + 1): down the meridian, then east: outward.
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const uint32_t a = vertex(i, j), b = vertex(i + 1, j), c = vertex(i + 1, j + 1),
                     d = vertex(i, j + 1);
      if (i + 1 < rings) body.mesh.indices.insert(body.mesh.indices.end(), {a, b, c});
      if (i > 0) body.mesh.indices.insert(body.mesh.indices.end(), {a, c, d});
    }
  body.voxel = {0.1, 0.1, 0.1};
  body.corner = {kX0, kY0, kZ0};
  body.name = "water";
  return body;
}

// Many blocks of triangles and of leaf columns: the same bytes on one thread as on all, and
// about the sphere's volume.
TEST(MeshFog, SameBytesForAnyThreadCount) {
  const FogBody sphere = sphere_body(150, 300);
  ASSERT_GT(sphere.mesh.indices.size() / 3, 80000u);
  const VolumeContent all = mesh_to_fog({sphere}, kVolumeOrigin, "sphere");
  {
    const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
    EXPECT_EQ(mesh_to_fog({sphere}, kVolumeOrigin, "sphere").vdb, all.vdb);
  }
  const openvdb::GridPtrVec grids = decode_volume(all, "sphere");
  ASSERT_EQ(grids.size(), 1u);
  const double volume = double(grids[0]->activeVoxelCount()) * 1e-3;  // voxels of 1e-3 m^3
  EXPECT_NEAR(volume, 4.0 / 3.0 * M_PI * 125, 0.005 * 4.0 / 3.0 * M_PI * 125);
}

TEST(MeshFog, PluginEntryGivesEachBodysVoxels) {
  auto* entry = plugin_function<decltype(maquette_vdb_mesh_fog)>(kVdbPlugin, kVdbMeshFogEntry);
  VolumeContent volume;
  entry({box_body(), turned_box()}, kVolumeOrigin, "box", volume);
  EXPECT_EQ(volume.origin, kVolumeOrigin);
  const openvdb::GridPtrVec grids = decode_volume(volume, "box");
  ASSERT_EQ(grids.size(), 2u);
  expect_the_box_s_voxels(grids[0], 0);
  expect_the_box_s_voxels(grids[1], 0.5);
  // Errors cross the plug-in's boundary as maquette::Error, naming `where` and the body.
  FogBody flat = box_body();
  flat.voxel[2] = 0;
  FogBody broken = box_body();
  broken.mesh.indices[4] = 8;
  for (const FogBody& bad : {flat, broken}) try {
      entry({box_body(), bad}, kVolumeOrigin, "deform.water, cell N3021", volume);
      ADD_FAILURE() << "accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("deform.water, cell N3021, body 1: "), std::string::npos)
          << e.what();
    }
}

TEST(MeshFog, BodyBeyondTheGridsCoordinatesIsRefused) {
  // 10 m in voxels of 2 nm: 5e9 voxels along x, beyond 2^31.
  FogBody tiny_voxels = box_body();
  tiny_voxels.voxel[0] = 2e-9;
  // The lattice's corner 3e9 voxels of 0.5 m north of the box (a lake far from its corner).
  FogBody far_corner = box_body();
  far_corner.corner[1] = kY0 + 1.5e9;
  for (const auto& [body, axis, voxel] : {std::tuple{tiny_voxels, "along x", "voxels of 2e-09 m"},
                                          std::tuple{far_corner, "along y", "voxels of 0.5 m"}})
    try {
      mesh_to_fog({box_body(), body}, kVolumeOrigin, "deform.water, cell N3021");
      ADD_FAILURE() << axis << ": accepted";
    } catch (const Error& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("deform.water, cell N3021, body 1: the mesh spans "), std::string::npos)
          << what;
      EXPECT_NE(what.find(axis), std::string::npos) << what;
      EXPECT_NE(what.find(voxel), std::string::npos) << what;
      EXPECT_NE(what.find("beyond a grid's 32-bit voxel coordinates"), std::string::npos) << what;
    }
}

}  // namespace
}  // namespace maquette::test
