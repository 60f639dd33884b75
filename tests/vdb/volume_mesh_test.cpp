// Volumes meshed (formats/vdb/volume_mesh.h), checked against analytic shapes: a sphere's area
// and enclosed volume, a box's extents; closed, outward, deterministic meshes.
#include "vdb/volume_mesh.h"

#include <gtest/gtest.h>
#include <oneapi/tbb/global_control.h>

#include <map>

#include "core/error.h"
#include "vdb/volume_vdb.h"
#include "vdb_fixture.h"

namespace maquette::test {
namespace {

using openvdb::Vec3d;

Vec3d vertex(const MeshObject& object, uint32_t v) {
  return Vec3d(object.positions[3 * v], object.positions[3 * v + 1], object.positions[3 * v + 2]);
}

struct Measures {
  double area = 0, volume = 0;
  size_t open_edges = 0;  // directed edges without their reverse, or repeated
};

// Area, and enclosed volume by the divergence theorem (sum of the signed tetrahedra from the
// origin: positive when the triangles are counter-clockwise seen from outside). A closed,
// consistently wound surface has every directed edge once and its reverse once.
Measures measure(const MeshObject& object) {
  Measures m;
  std::map<std::pair<uint32_t, uint32_t>, int> edges;
  for (size_t t = 0; t < object.indices.size(); t += 3) {
    const uint32_t* tri = &object.indices[t];
    const Vec3d a = vertex(object, tri[0]), b = vertex(object, tri[1]), c = vertex(object, tri[2]);
    m.area += 0.5 * (b - a).cross(c - a).length();
    m.volume += a.dot(b.cross(c)) / 6;
    for (int k = 0; k < 3; ++k) ++edges[{tri[k], tri[(k + 1) % 3]}];
  }
  for (const auto& [edge, count] : edges) {
    const auto reverse = edges.find({edge.second, edge.first});
    if (count != 1 || reverse == edges.end() || reverse->second != 1) ++m.open_edges;
  }
  return m;
}

MeshContent mesh_of(const openvdb::GridPtrVec& grids, const VolumeMeshSettings& settings = {}) {
  return volume_to_mesh(encode_volume(grids, kVolumeOrigin), settings, "test volume");
}

TEST(VolumeMesh, SphereIsClosedOutwardAndMeasuresRight) {
  const MeshContent mesh = mesh_of({sphere_level_set("lake")});
  EXPECT_EQ(mesh.origin, kVolumeOrigin);
  ASSERT_EQ(mesh.objects.size(), 1u);
  const MeshObject& sphere = mesh.objects[0];
  ASSERT_GT(sphere.indices.size(), 3000u);
  ASSERT_EQ(sphere.normals.size(), sphere.positions.size());
  EXPECT_TRUE(sphere.uvs.empty());

  const Measures m = measure(sphere);
  EXPECT_EQ(m.open_edges, 0u);
  const double r = kSphereRadius;
  EXPECT_NEAR(m.area, 4 * M_PI * r * r, 0.01 * 4 * M_PI * r * r);
  // Positions are offset from the frame's origin: the signed volume is that of the sphere only
  // if the surface is closed and wound outwards.
  EXPECT_NEAR(m.volume, 4 * M_PI * r * r * r / 3, 0.01 * 4 * M_PI * r * r * r / 3);

  double worst_radius = 0, worst_normal = 1, worst_face = 1;
  for (uint32_t v = 0; v < sphere.positions.size() / 3; ++v) {
    const Vec3d radial = vertex(sphere, v) - kSphereCentre;
    worst_radius = std::max(worst_radius, std::abs(radial.length() - r));
    const Vec3d n(sphere.normals[3 * v], sphere.normals[3 * v + 1], sphere.normals[3 * v + 2]);
    EXPECT_NEAR(n.length(), 1, 1e-6);
    worst_normal = std::min(worst_normal, n.dot(radial.unit()));
  }
  for (size_t t = 0; t < sphere.indices.size(); t += 3) {
    const Vec3d a = vertex(sphere, sphere.indices[t]), b = vertex(sphere, sphere.indices[t + 1]),
                c = vertex(sphere, sphere.indices[t + 2]);
    worst_face = std::min(
        worst_face, (b - a).cross(c - a).unit().dot(((a + b + c) / 3 - kSphereCentre).unit()));
  }
  // Measured: 2.3 mm, cos 0.9999995 (the sphere's distance field is exactly radial), cos 0.997.
  EXPECT_LT(worst_radius, 0.02 * kSphereVoxel);
  EXPECT_GT(worst_normal, 0.9999);  // vertex normals: the gradient, outwards
  EXPECT_GT(worst_face, 0.99);      // every triangle faces outwards
}

TEST(VolumeMesh, FogBoxExtentsAtItsIsovalue) {
  // Voxels 4..23 x -6..5 x 10..17 of 0.5 m: density 1 at their centres, 0 outside, so the 0.5
  // crossing lies half a voxel beyond the outer centres, on the box's faces (asked: within one
  // voxel; found exactly there).
  const double voxel = 0.5;
  const openvdb::CoordBBox box({4, -6, 10}, {23, 5, 17});
  const MeshContent mesh = mesh_of({fog_box(box, voxel, "cloud")});
  ASSERT_EQ(mesh.objects.size(), 1u);
  const MeshObject& object = mesh.objects[0];
  Vec3d lo(1e30), hi(-1e30);
  for (uint32_t v = 0; v < object.positions.size() / 3; ++v) {
    lo = openvdb::math::minComponent(lo, vertex(object, v));
    hi = openvdb::math::maxComponent(hi, vertex(object, v));
  }
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_NEAR(lo[axis], (box.min()[axis] - 0.5) * voxel, 0.01 * voxel) << axis;
    EXPECT_NEAR(hi[axis], (box.max()[axis] + 0.5) * voxel, 0.01 * voxel) << axis;
  }
  const Measures m = measure(object);
  EXPECT_EQ(m.open_edges, 0u);
  // The box less its edges and corners, cut over about half a voxel (235.2 m3 of 240 m3).
  const Vec3d size = hi - lo;
  const double box_volume = size[0] * size[1] * size[2];
  EXPECT_LT(m.volume, box_volume);
  EXPECT_GT(m.volume, 0.97 * box_volume);
  // The fog volume's gradient points inwards: its normals must not.
  const Vec3d centre = (lo + hi) / 2;
  for (uint32_t v = 0; v < object.positions.size() / 3; ++v) {
    const Vec3d n(object.normals[3 * v], object.normals[3 * v + 1], object.normals[3 * v + 2]);
    EXPECT_GT(n.dot(vertex(object, v) - centre), 0) << v;
  }
}

TEST(VolumeMesh, AdaptivityMergesFlatPolygons) {
  const MeshContent fine = mesh_of({sphere_level_set("lake")});
  const MeshContent coarse = mesh_of({sphere_level_set("lake")}, {.adaptivity = 0.5});
  ASSERT_EQ(coarse.objects.size(), 1u);
  // 1,166 triangles instead of 60,352, the volume 2.3 % short: flat facets across the curvature.
  EXPECT_LT(coarse.objects[0].indices.size(), fine.objects[0].indices.size() / 20);
  const double v = 4 * M_PI * std::pow(kSphereRadius, 3) / 3;
  const Measures m = measure(coarse.objects[0]);
  EXPECT_EQ(m.open_edges, 0u);
  EXPECT_NEAR(m.volume, v, 0.03 * v);
}

TEST(VolumeMesh, SameBitsOnAnyThreadCount) {
  const MeshContent many = mesh_of({sphere_level_set("lake")});
  const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  const MeshContent one = mesh_of({sphere_level_set("lake")});
  ASSERT_EQ(one.objects.size(), 1u);
  EXPECT_EQ(one.objects[0].positions, many.objects[0].positions);
  EXPECT_EQ(one.objects[0].normals, many.objects[0].normals);
  EXPECT_EQ(one.objects[0].indices, many.objects[0].indices);
}

TEST(VolumeMesh, MaterialAndProvenanceFromTheGrids) {
  auto water = sphere_level_set("lake");
  water->insertMeta("material", openvdb::StringMetadata("water"));
  water->insertMeta("object_id", openvdb::Int64Metadata(7001));
  water->insertMeta("feature_id", openvdb::Int64Metadata(42));
  water->insertMeta("tool", openvdb::StringMetadata("deform.water"));
  const auto named_water = fog_box(openvdb::CoordBBox({0, 0, 0}, {3, 3, 3}), 1, "water");
  const auto rock = fog_box(openvdb::CoordBBox({10, 0, 0}, {13, 3, 3}), 1, "rock");
  const auto empty = openvdb::FloatGrid::create(0.0f);  // no surface: no object
  const MeshContent mesh = mesh_of({water, named_water, rock, empty});
  ASSERT_EQ(mesh.objects.size(), 3u);
  ASSERT_EQ(mesh.materials.size(), 1u);
  const Material& m = mesh.materials[0];
  EXPECT_EQ(m.name, "water");
  EXPECT_GT(m.base_colour[2], m.base_colour[0]);  // blue
  EXPECT_LT(m.base_colour[3], 1);                 // see-through
  EXPECT_EQ(mesh.objects[0].material, 0);
  EXPECT_EQ(mesh.objects[1].material, 0);
  EXPECT_EQ(mesh.objects[2].material, -1);  // the default grey
  EXPECT_EQ(mesh.objects[0].provenance.object_id, 7001u);
  EXPECT_EQ(mesh.objects[0].provenance.feature_id, 42);
  EXPECT_EQ(mesh.objects[0].provenance.tool, "deform.water");
  EXPECT_EQ(mesh.objects[2].provenance, ObjectProvenance{});
}

TEST(VolumeMesh, BadVolumesAreNamed) {
  const auto fails = [](const VolumeContent& volume, const std::string& message) {
    try {
      volume_to_mesh(volume, {}, "layer lakes, cell N3021");
      ADD_FAILURE() << message << ": meshed";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  };
  const VolumeContent good = encode_volume({sphere_level_set("lake")}, kVolumeOrigin);
  fails({kVolumeOrigin, good.vdb.substr(0, good.vdb.size() / 3)},
        "layer lakes, cell N3021: the volume is not a whole VDB stream");
  auto velocity = openvdb::Vec3SGrid::create();
  velocity->setName("flow");
  velocity->tree().setValueOn({0, 0, 0}, openvdb::Vec3s(1, 0, 0));
  fails(encode_volume({velocity}, kVolumeOrigin),
        "layer lakes, cell N3021: grid 'flow' holds vec3s values");
  auto typo = sphere_level_set("lake");
  typo->insertMeta("object_id", openvdb::StringMetadata("7001"));
  fails(encode_volume({typo}, kVolumeOrigin),
        "layer lakes, cell N3021: grid 'lake': metadata 'object_id' is of type string, not int64");
}

}  // namespace
}  // namespace maquette::test
