// with_facet_normals (content/facet_normals.h): a box's corners split into one vertex per face
// meeting there, each with its face's normal, computed here by hand; the triangles of one planar
// face share their vertices; positions, uvs, the triangles' order and the first vertex kept, also
// when no triangle uses it; and the same bits as the first implementation (a vector of
// orientations per vertex, kept here as the oracle) on generated lake-like and building-like
// meshes.
#include "content/facet_normals.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/splitmix64.h"

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

TEST(FacetNormals, AnUnusedVertexKeepsOneCopyFacingUp) {
  // A square facing down behind an unused anchor (vertex 0), with another unused vertex (3).
  MeshObject square;
  square.positions = {5, 6, 7, 0, 0, 0, 1, 0, 0, 9, 9, 9, 1, 1, 0, 0, 1, 0};
  square.uvs = {0.5f, 0.25f, 0, 0, 1, 0, 0.75f, 0.125f, 1, 1, 0, 1};
  square.indices = {1, 4, 2, 1, 5, 4};
  const MeshObject out = with_facet_normals(square);
  EXPECT_EQ(out.positions, square.positions);
  EXPECT_EQ(out.uvs, square.uvs);
  EXPECT_EQ(out.indices, square.indices);
  EXPECT_EQ(out.normals,
            (std::vector<float>{0, 0, 1, 0, 0, -1, 0, 0, -1, 0, 0, 1, 0, 0, -1, 0, 0, -1}));
}

// The first implementation, kept as the oracle of the present one's bits: per vertex a vector of
// its orientations in the order met, each corner taking the first within kFacetNormalTurnDeg of
// its face's normal, the copies in vertex order; a degenerate face's corner (no area, or lower
// than kFacetMinHeightM over its longest side) takes the first orientation of its vertex's other
// faces, +z when none.
MeshObject facet_normals_by_vertex_vectors(const MeshObject& object) {
  const size_t vertices = object.positions.size() / 3, triangles = object.indices.size() / 3;
  const auto position = [&](uint32_t v) {
    return std::array<double, 3>{object.positions[3 * v], object.positions[3 * v + 1],
                                 object.positions[3 * v + 2]};
  };
  const double min_dot = std::cos(kFacetNormalTurnDeg * std::numbers::pi / 180);
  std::vector<std::vector<std::array<double, 3>>> orientations(vertices);
  std::vector<uint32_t> corner_orientation(object.indices.size());
  std::vector<size_t> degenerate;  // triangles
  for (size_t t = 0; t < triangles; ++t) {
    const auto a = position(object.indices[3 * t]), b = position(object.indices[3 * t + 1]),
               c = position(object.indices[3 * t + 2]);
    const std::array<double, 3> u{b[0] - a[0], b[1] - a[1], b[2] - a[2]},
        w{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    std::array<double, 3> n{u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
                            u[0] * w[1] - u[1] * w[0]};
    const double length = std::hypot(n[0], n[1], n[2]);
    const double longest = std::max({std::hypot(u[0], u[1], u[2]), std::hypot(w[0], w[1], w[2]),
                                     std::hypot(w[0] - u[0], w[1] - u[1], w[2] - u[2])});
    if (!(length > kFacetMinHeightM * longest)) {
      degenerate.push_back(t);
      continue;
    }
    for (double& x : n) x /= length;
    for (size_t k = 0; k < 3; ++k) {
      std::vector<std::array<double, 3>>& own = orientations[object.indices[3 * t + k]];
      size_t o = 0;
      while (o < own.size() && own[o][0] * n[0] + own[o][1] * n[1] + own[o][2] * n[2] < min_dot)
        ++o;
      if (o == own.size()) own.push_back(n);
      corner_orientation[3 * t + k] = uint32_t(o);
    }
  }
  for (const size_t t : degenerate)
    for (size_t k = 0; k < 3; ++k) {
      std::vector<std::array<double, 3>>& own = orientations[object.indices[3 * t + k]];
      if (own.empty()) own.push_back({0, 0, 1});
      corner_orientation[3 * t + k] = 0;
    }
  MeshObject out;
  std::vector<uint32_t> first_copy(vertices);
  for (uint32_t v = 0; v < vertices; ++v) {
    first_copy[v] = uint32_t(out.positions.size() / 3);
    for (const std::array<double, 3>& n : orientations[v]) {
      out.positions.insert(out.positions.end(), object.positions.begin() + 3 * v,
                           object.positions.begin() + 3 * v + 3);
      if (!object.uvs.empty())
        out.uvs.insert(out.uvs.end(), object.uvs.begin() + 2 * v, object.uvs.begin() + 2 * v + 2);
      out.normals.insert(out.normals.end(), {float(n[0]), float(n[1]), float(n[2])});
    }
  }
  for (size_t c = 0; c < object.indices.size(); ++c)
    out.indices.push_back(first_copy[object.indices[c]] + corner_orientation[c]);
  return out;
}

// Draws doubles uniform in [lo, hi) from a SplitMix64 stream.
struct Draw {
  uint64_t state;
  double operator()(double lo, double hi) {
    return lo + (hi - lo) * unit_interval(splitmix64_next(state));
  }
};

void add_vertex(MeshObject& m, double x, double y, double z) {
  m.positions.insert(m.positions.end(), {float(x), float(y), float(z)});
  m.uvs.insert(m.uvs.end(), {float(x / 64), float(y / 64)});
}

void add_quad(MeshObject& m, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
  m.indices.insert(m.indices.end(), {a, b, c, a, c, d});
}

// A lake on a 48 x 40 lattice of 1 m pixels, as water_mesh.h builds one: a flat top at the level,
// a bottom following a terrain whose neighbouring quads turn by about kFacetNormalTurnDeg (some
// share a vertex copy, some not, several copies at many corners), and walls around.
MeshObject lake_like() {
  constexpr uint32_t kCols = 48, kRows = 40, kCorners = (kCols + 1) * (kRows + 1);
  Draw draw{17};
  MeshObject m;
  for (uint32_t r = 0; r <= kRows; ++r)
    for (uint32_t c = 0; c <= kCols; ++c) add_vertex(m, c, -double(r), 10);
  for (uint32_t r = 0; r <= kRows; ++r)
    for (uint32_t c = 0; c <= kCols; ++c)
      add_vertex(m, c, -double(r), 2 + 0.01 * c + draw(-0.012, 0.012));
  const auto top = [&](uint32_t c, uint32_t r) { return r * (kCols + 1) + c; };
  const auto bottom = [&](uint32_t c, uint32_t r) { return kCorners + top(c, r); };
  for (uint32_t r = 0; r < kRows; ++r)
    for (uint32_t c = 0; c < kCols; ++c) {
      add_quad(m, top(c, r + 1), top(c + 1, r + 1), top(c + 1, r), top(c, r));
      add_quad(m, bottom(c, r), bottom(c + 1, r), bottom(c + 1, r + 1), bottom(c, r + 1));
    }
  for (uint32_t c = 0; c < kCols; ++c) {
    add_quad(m, top(c, 0), top(c + 1, 0), bottom(c + 1, 0), bottom(c, 0));  // north
    add_quad(m, top(c + 1, kRows), top(c, kRows), bottom(c, kRows), bottom(c + 1, kRows));
  }
  for (uint32_t r = 0; r < kRows; ++r) {
    add_quad(m, top(0, r + 1), top(0, r), bottom(0, r), bottom(0, r + 1));  // west
    add_quad(m, top(kCols, r), top(kCols, r + 1), bottom(kCols, r + 1), bottom(kCols, r));
  }
  return m;
}

// 30 buildings as structures.buildings makes them: random polygon footprints extruded, walls of
// two triangles, roofs fanned from their first corner and tilted by 0 to 2 degrees, each with a
// degenerate triangle (a corner repeated); then a flat one (three corners in a line).
MeshObject building_like() {
  Draw draw{29};
  MeshObject m;
  for (int building = 0; building < 30; ++building) {
    const double x0 = draw(0, 500), y0 = draw(0, 500), radius = draw(4, 20), ground = draw(-2, 2),
                 eaves = ground + draw(3, 40);
    const double tilt = std::tan(draw(0, 2) * std::numbers::pi / 180), azimuth = draw(0, 6.3);
    const uint32_t sides = uint32_t(draw(3, 13)), first = uint32_t(m.positions.size() / 3);
    const size_t faces_begin = m.indices.size();
    double angle = 0;
    for (uint32_t s = 0; s < sides; ++s, angle += draw(0.5, 1.5) * 2 * std::numbers::pi / sides) {
      const double x = x0 + radius * std::cos(angle), y = y0 + radius * std::sin(angle);
      add_vertex(m, x, y, ground);
      add_vertex(m, x, y,
                 eaves + tilt * ((x - x0) * std::cos(azimuth) + (y - y0) * std::sin(azimuth)));
    }
    const auto low = [&](uint32_t s) { return first + 2 * (s % sides); };
    for (uint32_t s = 0; s < sides; ++s)
      add_quad(m, low(s), low(s + 1), low(s + 1) + 1, low(s) + 1);
    for (uint32_t s = 1; s + 1 < sides; ++s)
      m.indices.insert(m.indices.end(),
                       {low(0) + 1, low(s) + 1, low(s + 1) + 1, low(0), low(s + 1), low(s)});
    // A degenerate triangle on the roof, before the building's faces (its corners' first
    // orientation then up, which the roof may join) or after them.
    m.indices.insert(building % 2 ? m.indices.end() : m.indices.begin() + faces_begin,
                     {low(1) + 1, low(1) + 1, low(2) + 1});
  }
  add_vertex(m, 0, 0, 0);
  add_vertex(m, 1, 1, 1);
  add_vertex(m, 2, 2, 2);
  const uint32_t last = uint32_t(m.positions.size() / 3);
  m.indices.insert(m.indices.end(), {last - 3, last - 2, last - 1});
  return m;
}

void expect_same_bits_as_the_oracle(const MeshObject& in) {
  const MeshObject out = with_facet_normals(in), want = facet_normals_by_vertex_vectors(in);
  EXPECT_EQ(out.positions, want.positions);
  EXPECT_EQ(out.normals, want.normals);
  EXPECT_EQ(out.uvs, want.uvs);
  EXPECT_EQ(out.indices, want.indices);
}

TEST(FacetNormals, LakeLikeMeshHasTheFirstImplementationsBits) {
  const MeshObject in = lake_like();
  expect_same_bits_as_the_oracle(in);
  // Not a trivial case: the walls split the rims' 356 vertices (< 400 more copies), the bottom's
  // turns many more of its corners, though not all (a split bottom would need ~11,000 copies).
  const size_t copies = with_facet_normals(in).positions.size() / 3;
  EXPECT_GT(copies, in.positions.size() / 3 + 1000);
  EXPECT_LT(copies, in.indices.size() / 3);
}

TEST(FacetNormals, BuildingLikeMeshHasTheFirstImplementationsBits) {
  expect_same_bits_as_the_oracle(building_like());
}

}  // namespace
}  // namespace maquette
