// lake_mesh (water_mesh.h): closed (each edge in exactly two triangles, once in each
// direction), its enclosed volume (divergence theorem) close to the raster volume, the top
// triangulated from the shoreline (no vertex inside the lake but fan centroids).
#include "../water_mesh.h"

#include <gtest/gtest.h>

#include <map>
#include <utility>

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

void expect_closed_and_oriented(const LakeMesh& m) {
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

TEST(WaterMesh, HillsLakeIsClosedWithTheRasterVolume) {
  const Basin b = hills();
  const WaterBody body = fill_basin(b.raster(), water_level(b.raster(), {}));
  const LakeMesh m = lake_mesh(b.raster(), body);
  expect_closed_and_oriented(m);
  EXPECT_NEAR(enclosed_volume(m, b.pixel_m), body.volume_m3, 0.01 * body.volume_m3);
}

TEST(WaterMesh, ParaboloidTopHasOnlyShorelineVertices) {
  const Basin b = paraboloid();
  const WaterBody body = fill_basin(b.raster(), 100);
  const LakeMesh m = lake_mesh(b.raster(), body);
  expect_closed_and_oriented(m);
  EXPECT_NEAR(enclosed_volume(m, b.pixel_m), body.volume_m3, 0.005 * body.volume_m3);
  // Top vertices (at the level, not on the corner lattice's wet interior): the shoreline's
  // corners and fan centroids, far fewer than the lake's pixels.
  size_t top = 0;
  for (const LakeVertex& v : m.vertices) top += v.height == body.level;
  EXPECT_LT(top, body.wet.size() / 20);
}

}  // namespace
}  // namespace maquette::deform
