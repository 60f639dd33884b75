#include "terrain_base.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace maquette::structures {
namespace {

// Crossing number over all rings (even-odd: holes count out).
bool inside(const std::vector<PixelRing>& rings, double x, double y) {
  bool in = false;
  for (const PixelRing& ring : rings)
    for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++)
      if ((ring[i][1] > y) != (ring[j][1] > y) &&
          x < ring[j][0] + (y - ring[j][1]) / (ring[i][1] - ring[j][1]) * (ring[i][0] - ring[j][0]))
        in = !in;
  return in;
}

}  // namespace

std::optional<float> lowest_terrain(const Tile<float>& dem, const std::vector<PixelRing>& rings) {
  double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
  for (const PixelRing& ring : rings)
    for (const PlanePoint2& p : ring) {
      x0 = std::min(x0, p[0]), x1 = std::max(x1, p[0]);
      y0 = std::min(y0, p[1]), y1 = std::max(y1, p[1]);
    }
  // Touched pixels and their neighbours: one pixel of margin on each side.
  const int c0 = int(std::floor(x0)) - 1, c1 = int(std::floor(x1)) + 1;
  const int r0 = int(std::floor(y0)) - 1, r1 = int(std::floor(y1)) + 1;
  const int lo = -dem.halo(), hi = dem.size() + dem.halo() - 1;
  const int beyond = std::max({lo - c0, lo - r0, c1 - hi, r1 - hi});
  if (beyond > 0)
    throw InvalidFootprint("the footprint reaches " + std::to_string(beyond) +
                           " pixels beyond the DEM tile's halo of " + std::to_string(dem.halo()) +
                           " pixels around its cell");
  const int w = c1 - c0 + 1, h = r1 - r0 + 1;
  std::vector<uint8_t> touched(size_t(w) * size_t(h), 0);
  const auto mark = [&](int c, int r) { touched[size_t(r - r0) * size_t(w) + size_t(c - c0)] = 1; };
  for (int r = r0 + 1; r < r1; ++r)
    for (int c = c0 + 1; c < c1; ++c)
      if (inside(rings, c + 0.5, r + 0.5)) mark(c, r);
  for (const PixelRing& ring : rings)
    for (size_t i = 0; i < ring.size(); ++i) {
      const PlanePoint2& a = ring[i];
      const PlanePoint2& b = ring[(i + 1) % ring.size()];
      const int steps = 1 + int(4 * std::max(std::abs(b[0] - a[0]), std::abs(b[1] - a[1])));
      for (int k = 0; k <= steps; ++k) {
        const double t = double(k) / steps;
        mark(int(std::floor(a[0] + t * (b[0] - a[0]))), int(std::floor(a[1] + t * (b[1] - a[1]))));
      }
    }
  float lowest = INFINITY;
  for (int r = r0 + 1; r < r1; ++r)
    for (int c = c0 + 1; c < c1; ++c) {
      if (!touched[size_t(r - r0) * size_t(w) + size_t(c - c0)]) continue;
      for (int dr = -1; dr <= 1; ++dr)
        for (int dc = -1; dc <= 1; ++dc) {
          const float z = dem.at(c + dc, r + dr);
          if (z < lowest) lowest = z;  // NaN compares false: skipped
        }
    }
  if (std::isinf(lowest)) return std::nullopt;
  return lowest;
}

}  // namespace maquette::structures
