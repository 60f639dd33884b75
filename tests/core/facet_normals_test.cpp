// with_facet_normals (content/facet_normals.h): a box's corners split into one vertex per face
// meeting there, each with its face's normal, computed here by hand; the triangles of one planar
// face share their vertices; positions, uvs, the triangles' order and the first vertex kept.
#include "content/facet_normals.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

namespace maquette {
namespace {

// A unit cube's 8 corners, its 12 triangles counter-clockwise seen from outside, and uvs.
MeshObject cube() {
  MeshObject m;
  for (int k = 0; k < 8; ++k) {
    m.positions.insert(m.positions.end(), {float(k & 1), float((k >> 1) & 1), float(k >> 2)});
    m.uvs.insert(m.uvs.end(), {float(k) / 8, 1 - float(k) / 8});
  }
  m.indices = {0, 2, 3, 0, 3, 1,   // z = 0, down
               4, 5, 7, 4, 7, 6,   // z = 1, up
               0, 1, 5, 0, 5, 4,   // y = 0, south
               2, 6, 7, 2, 7, 3,   // y = 1, north
               0, 4, 6, 0, 6, 2,   // x = 0, west
               1, 3, 7, 1, 7, 5};  // x = 1, east
  return m;
}

TEST(FacetNormals, CubeCornersSplitIntoOneVertexPerFace) {
  const MeshObject in = cube();
  const MeshObject out = with_facet_normals(in);
  ASSERT_EQ(out.indices.size(), in.indices.size());
  EXPECT_EQ(out.positions.size(), 24u * 3);  // 6 faces x 4 corners
  ASSERT_EQ(out.normals.size(), out.positions.size());
  ASSERT_EQ(out.uvs.size(), 24u * 2);
  for (size_t c = 0; c < 3; ++c) EXPECT_EQ(out.positions[c], in.positions[c]);  // the anchor
  const std::array<std::array<float, 3>, 6> want = {
      {{0, 0, -1}, {0, 0, 1}, {0, -1, 0}, {0, 1, 0}, {-1, 0, 0}, {1, 0, 0}}};
  for (size_t t = 0; t < in.indices.size() / 3; ++t)
    for (size_t k = 0; k < 3; ++k) {
      const uint32_t a = in.indices[3 * t + k], b = out.indices[3 * t + k];
      for (size_t c = 0; c < 3; ++c) {
        EXPECT_EQ(out.positions[3 * b + c], in.positions[3 * a + c]);
        EXPECT_EQ(out.normals[3 * b + c], want[t / 2][c]) << "triangle " << t;
      }
      EXPECT_EQ(out.uvs[2 * b], in.uvs[2 * a]);
      EXPECT_EQ(out.uvs[2 * b + 1], in.uvs[2 * a + 1]);
    }
}

TEST(FacetNormals, TrianglesOfOnePlaneShareTheirVertices) {
  // A square roof tilted by 30 degrees about x, in two triangles.
  MeshObject roof;
  const float c = float(std::cos(std::numbers::pi / 6)), s = float(std::sin(std::numbers::pi / 6));
  roof.positions = {0, 0, 0, 1, 0, 0, 1, c, s, 0, c, s};
  roof.indices = {0, 1, 2, 0, 2, 3};
  const MeshObject out = with_facet_normals(roof);
  EXPECT_EQ(out.positions.size(), 12u);
  for (size_t v = 0; v < 4; ++v) {
    EXPECT_NEAR(out.normals[3 * v], 0, 1e-7);
    EXPECT_NEAR(out.normals[3 * v + 1], -s, 1e-7);
    EXPECT_NEAR(out.normals[3 * v + 2], c, 1e-7);
  }
}

}  // namespace
}  // namespace maquette
