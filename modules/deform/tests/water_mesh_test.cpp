// lake_mesh (water_mesh.h): closed (each edge in exactly two triangles, once in each
// direction), no degenerate triangle, its enclosed volume (divergence theorem) the lake's area
// times the prism's height; the top and the bottom triangulated from the shoreline (no vertex
// inside the lake); the same mesh for any thread count.
#include "../water_mesh.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <utility>
#include <vector>

#include "water_basins.h"

namespace maquette::deform {
namespace {

// Signed volume of a closed mesh in the frame (col, -row, height) scaled by pixel_m.
double enclosed_volume(const LakeMesh& m, double pixel_m) {
  double v = 0;
  for (size_t t = 0; t < m.indices.size(); t += 3) {
    double p[3][3];
    for (int k = 0; k < 3; ++k) {
      const LakeVertex& q = m.vertices[m.indices[t + size_t(k)]];
      p[k][0] = q.col * pixel_m;
      p[k][1] = -q.row * pixel_m;
      p[k][2] = q.height;
    }
    v += p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) -
         p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0]) +
         p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0]);
  }
  return v / 6;
}

// Triangles of zero area (in the frame (col, -row, height)).
size_t degenerate_triangles(const LakeMesh& m) {
  size_t n = 0;
  for (size_t t = 0; t < m.indices.size(); t += 3) {
    const LakeVertex &a = m.vertices[m.indices[t]], &b = m.vertices[m.indices[t + 1]],
                     &c = m.vertices[m.indices[t + 2]];
    const double u[3] = {b.col - a.col, a.row - b.row, b.height - a.height};
    const double v[3] = {c.col - a.col, a.row - c.row, c.height - a.height};
    n += u[1] * v[2] - u[2] * v[1] == 0 && u[2] * v[0] - u[0] * v[2] == 0 &&
         u[0] * v[1] - u[1] * v[0] == 0;
  }
  return n;
}

void expect_closed_and_oriented(const LakeMesh& m) {
  EXPECT_EQ(degenerate_triangles(m), 0u) << "of " << m.indices.size() / 3 << " triangles";
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  for (size_t t = 0; t < m.indices.size(); t += 3)
    for (size_t e = 0; e < 3; ++e) ++directed[{m.indices[t + e], m.indices[t + (e + 1) % 3]}];
  size_t faults = 0;
  for (const auto& [edge, n] : directed) {
    const auto reverse = directed.find({edge.second, edge.first});
    faults += n != 1 || reverse == directed.end() || reverse->second != 1;
  }
  EXPECT_EQ(faults, 0u) << "of " << directed.size() << " directed edges";
}

// Built by blocks of rows in parallel (16 blocks here): the same vertices and triangles on one
// thread as on all.
TEST(WaterMesh, SameMeshForOneThreadAndMore) {
  const Basin b = hills(1000, 1000);
  const WaterBody body = fill_basin(b.raster(), water_level(b.raster(), {}));
  LakeMesh one;
  {
    const tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    one = lake_mesh(b.raster(), body, lake_flat_bottom(b.raster(), body));
  }
  const LakeMesh many = lake_mesh(b.raster(), body, lake_flat_bottom(b.raster(), body));
  EXPECT_EQ(one.indices, many.indices);
  ASSERT_EQ(one.vertices.size(), many.vertices.size());
  for (size_t i = 0; i < one.vertices.size(); ++i) {
    ASSERT_EQ(one.vertices[i].col, many.vertices[i].col) << i;
    ASSERT_EQ(one.vertices[i].row, many.vertices[i].row) << i;
    ASSERT_EQ(one.vertices[i].height, many.vertices[i].height) << i;
  }
}

// Whether corner (col, row) touches a dry pixel.
bool on_shore(const Basin& b, const WaterBody& body, const LakeVertex& v) {
  const int64_t c = int64_t(v.col), r = int64_t(v.row);
  bool shore = false;
  for (int q = 0; q < 4; ++q) {
    const int64_t pc = c - 1 + (q & 1), pr = r - 1 + (q >> 1);
    shore = shore || !std::binary_search(body.wet.begin(), body.wet.end(), pr * b.width + pc);
  }
  return shore;
}

// The flat bottom: the prism of the lake's outline (islands as holes), 1 m below its lowest bed;
// every vertex a shoreline corner, at the level or at the bottom; its volume the wet pixels'
// area times the prism's height (the divergence theorem's sum, to rounding). Returns the mesh.
LakeMesh expect_flat_prism(const Basin& b, const WaterBody& body) {
  const LakeMesh flat = lake_mesh(b.raster(), body, lake_flat_bottom(b.raster(), body));
  expect_closed_and_oriented(flat);
  float lowest = INFINITY;
  for (const int64_t i : body.wet) lowest = std::min(lowest, b.terrain[size_t(i)]);
  const double floor = double(lowest) - 1;
  EXPECT_EQ(lake_flat_bottom(b.raster(), body), floor);
  const double area = double(body.wet.size()) * b.pixel_m * b.pixel_m;
  EXPECT_NEAR(enclosed_volume(flat, b.pixel_m), area * (body.level - floor),
              1e-9 * area * (body.level - floor));
  size_t faults = 0;
  for (const LakeVertex& v : flat.vertices)
    faults += !on_shore(b, body, v) || (v.height != body.level && v.height != floor);
  EXPECT_EQ(faults, 0u) << "of " << flat.vertices.size() << " vertices";
  std::printf("%zu triangles, %zu vertices for %zu wet pixels\n", flat.indices.size() / 3,
              flat.vertices.size(), body.wet.size());
  return flat;
}

TEST(WaterMesh, FlatBottomMakesThePrismOfTheShoreline) {
  const Basin p = paraboloid();
  const WaterBody round = fill_basin(p.raster(), 100);
  // The shoreline's corners only, at the top and the bottom: far fewer than the lake's pixels.
  EXPECT_LT(expect_flat_prism(p, round).vertices.size(), round.wet.size() / 10);
  const Basin h = hills(600, 500);
  expect_flat_prism(h, fill_basin(h.raster(), water_level(h.raster(), {})));
  const Basin large = hills(1000, 1000);
  expect_flat_prism(large, fill_basin(large.raster(), water_level(large.raster(), {})));
}

}  // namespace
}  // namespace maquette::deform
