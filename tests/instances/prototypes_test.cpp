// The built-in prototypes: closed and consistently oriented (OpenMesh builds a manifold without
// boundary from their triangles, vertices at the same position merged), outward (positive
// volume, normals on the side of their triangles), of the size and shape their header gives, and
// made the same each time.
#include "content/prototypes.h"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <array>
#include <cmath>
#include <map>

#include "core/error.h"
#include "gtest/gtest.h"

namespace maquette {
namespace {

using Mesh = OpenMesh::TriMesh_ArrayKernelT<>;
using P = std::array<float, 3>;

P at(const std::vector<float>& v, uint32_t i) { return {v[3 * i], v[3 * i + 1], v[3 * i + 2]}; }
std::array<double, 3> cross(const P& a, const P& b, const P& c) {
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

class Prototype : public testing::TestWithParam<std::string> {};

TEST_P(Prototype, EachObjectIsClosedAndConsistentlyOriented) {
  const MeshContent& m = builtin_prototype(GetParam());
  ASSERT_EQ(m.objects.size(), 2u);
  for (const MeshObject& o : m.objects) {
    SCOPED_TRACE("object of material " + std::to_string(o.material));
    Mesh mesh;
    std::map<P, Mesh::VertexHandle> welded;
    std::vector<Mesh::VertexHandle> handle;
    for (uint32_t i = 0; i < o.positions.size() / 3; ++i) {
      const P p = at(o.positions, i);
      auto [it, added] = welded.try_emplace(p);
      if (added) it->second = mesh.add_vertex(Mesh::Point(p[0], p[1], p[2]));
      handle.push_back(it->second);
    }
    size_t refused = 0;
    for (size_t t = 0; t < o.indices.size(); t += 3)
      refused +=
          !mesh.add_face(handle[o.indices[t]], handle[o.indices[t + 1]], handle[o.indices[t + 2]])
               .is_valid();
    EXPECT_EQ(refused, 0u) << "triangles OpenMesh refused: complex edges or flipped triangles";
    size_t boundary = 0;
    for (const auto& h : mesh.halfedges()) boundary += mesh.is_boundary(h);
    EXPECT_EQ(boundary, 0u) << "boundary half-edges: the object is not closed";
    EXPECT_EQ(mesh.n_faces(), o.indices.size() / 3);
  }
}

TEST_P(Prototype, FacesOutwardWithUnitNormalsOnTheSideOfTheirTriangles) {
  for (const MeshObject& o : builtin_prototype(GetParam()).objects) {
    ASSERT_EQ(o.normals.size(), o.positions.size());
    for (size_t i = 0; i < o.normals.size(); i += 3)
      ASSERT_NEAR(std::hypot(o.normals[i], o.normals[i + 1], o.normals[i + 2]), 1, 1e-5);
    // The divergence theorem: a closed surface of outward triangles encloses a positive volume.
    double volume = 0;
    size_t against = 0;
    for (size_t t = 0; t < o.indices.size(); t += 3) {
      const P a = at(o.positions, o.indices[t]), b = at(o.positions, o.indices[t + 1]),
              c = at(o.positions, o.indices[t + 2]);
      const auto n = cross(a, b, c);
      volume += (a[0] * n[0] + a[1] * n[1] + a[2] * n[2]) / 6;
      for (size_t k = 0; k < 3; ++k) {
        const P v = at(o.normals, o.indices[t + k]);
        against += v[0] * n[0] + v[1] * n[1] + v[2] * n[2] <= 0;
      }
    }
    EXPECT_GT(volume, 1e-4) << "object of material " << o.material;
    EXPECT_EQ(against, 0u) << "vertex normals facing away from their triangle";
  }
}

// The header's contract: 1 m tall from z = 0, centred on the z axis, crowns of about the given
// diameter, fewer than 2,000 vertices.
TEST_P(Prototype, HasItsBoundingBox) {
  const std::map<std::string, std::pair<double, double>> crown = {
      {"builtin:conifer", {0.4, 0.65}},
      {"builtin:broadleaf", {0.6, 0.85}},
      {"builtin:shrub", {1.6, 2.2}}};
  const MeshContent& m = builtin_prototype(GetParam());
  std::array<double, 3> lo{1e9, 1e9, 1e9}, hi{-1e9, -1e9, -1e9};
  size_t vertices = 0;
  for (const MeshObject& o : m.objects) {
    vertices += o.positions.size() / 3;
    for (size_t i = 0; i < o.positions.size(); ++i) {
      lo[i % 3] = std::min(lo[i % 3], double(o.positions[i]));
      hi[i % 3] = std::max(hi[i % 3], double(o.positions[i]));
    }
  }
  EXPECT_EQ(lo[2], 0);
  EXPECT_EQ(hi[2], 1);
  for (int k = 0; k < 2; ++k) {
    EXPECT_NEAR((lo[k] + hi[k]) / 2, 0, 0.06) << "axis " << k;
    EXPECT_GE(hi[k] - lo[k], crown.at(GetParam()).first) << "axis " << k;
    EXPECT_LE(hi[k] - lo[k], crown.at(GetParam()).second) << "axis " << k;
  }
  EXPECT_LT(vertices, 2000u);
  ASSERT_EQ(m.materials.size(), 2u);
  EXPECT_EQ(m.objects[0].material, 0);
  EXPECT_EQ(m.objects[1].material, 1);
  // Bark is brown (red above green above blue), foliage green.
  const auto& bark = m.materials[0].base_colour;
  const auto& foliage = m.materials[1].base_colour;
  EXPECT_TRUE(bark[0] > bark[1] && bark[1] > bark[2]);
  EXPECT_TRUE(foliage[1] > foliage[0] && foliage[1] > foliage[2]);
}

TEST_P(Prototype, IsMadeTheSameEachTime) {
  const MeshContent a = make_builtin_prototype(GetParam());
  const MeshContent b = make_builtin_prototype(GetParam());
  const MeshContent& kept = builtin_prototype(GetParam());
  ASSERT_EQ(a.objects.size(), b.objects.size());
  for (size_t i = 0; i < a.objects.size(); ++i) {
    for (const MeshContent* other : {&b, &kept}) {
      const MeshObject& x = a.objects[i];
      const MeshObject& y = other->objects[i];
      ASSERT_EQ(x.positions.size(), y.positions.size());
      EXPECT_EQ(std::memcmp(x.positions.data(), y.positions.data(), x.positions.size() * 4), 0);
      EXPECT_EQ(std::memcmp(x.normals.data(), y.normals.data(), x.normals.size() * 4), 0);
      EXPECT_EQ(x.indices, y.indices);
    }
  }
  EXPECT_EQ(a.materials, b.materials);
}

INSTANTIATE_TEST_SUITE_P(Builtin, Prototype,
                         testing::Values("builtin:conifer", "builtin:broadleaf", "builtin:shrub"),
                         [](const auto& info) { return info.param.substr(8); });

TEST(Prototypes, AnUnknownNameIsAnErrorListingTheKnownOnes) {
  try {
    builtin_prototype("builtin:palm");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(),
                 "unknown prototype 'builtin:palm' (built in: builtin:conifer, builtin:broadleaf, "
                 "builtin:shrub)");
  }
  EXPECT_THROW(make_builtin_prototype("cone"), Error);
}

}  // namespace
}  // namespace maquette
