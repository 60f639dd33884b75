#include "terrain_base.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace maquette::structures {
namespace {

// Marks the pixels of rows r0..r1 whose centre lies inside the rings (even-odd: holes count
// out), by scanlines through the centres: between the 1st and 2nd crossing, the 3rd and 4th...
void mark_inside(const std::vector<PixelRing>& rings, int c0, int r0, int r1, int w,
                 std::vector<uint8_t>& mask) {
  std::vector<double> crossings;
  for (int r = r0; r <= r1; ++r) {
    const double y = r + 0.5;
    crossings.clear();
    for (const PixelRing& ring : rings)
      for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++)
        if ((ring[i][1] > y) != (ring[j][1] > y))
          crossings.push_back(ring[j][0] + (y - ring[j][1]) / (ring[i][1] - ring[j][1]) *
                                               (ring[i][0] - ring[j][0]));
    std::sort(crossings.begin(), crossings.end());
    for (size_t k = 0; k + 1 < crossings.size(); k += 2)
      for (int c = int(std::floor(crossings[k] - 0.5)) + 1; c + 0.5 < crossings[k + 1]; ++c)
        mask[size_t(r - r0) * size_t(w) + size_t(c - c0)] = 1;
  }
}

// The mask grown by one pixel in each of the 8 directions (separably: along rows, then columns).
std::vector<uint8_t> dilate(const std::vector<uint8_t>& mask, int w, int h) {
  std::vector<uint8_t> rows(mask.size(), 0), out(mask.size(), 0);
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      const size_t i = size_t(r) * size_t(w) + size_t(c);
      rows[i] = mask[i] | (c > 0 ? mask[i - 1] : 0) | (c + 1 < w ? mask[i + 1] : 0);
    }
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      const size_t i = size_t(r) * size_t(w) + size_t(c);
      out[i] = rows[i] | (r > 0 ? rows[i - size_t(w)] : 0) | (r + 1 < h ? rows[i + size_t(w)] : 0);
    }
  return out;
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
  mark_inside(rings, c0, r0 + 1, r1 - 1, w, touched);
  for (const PixelRing& ring : rings)
    for (size_t i = 0; i < ring.size(); ++i) {
      const PlanePoint2& a = ring[i];
      const PlanePoint2& b = ring[(i + 1) % ring.size()];
      const int steps = 1 + int(4 * std::max(std::abs(b[0] - a[0]), std::abs(b[1] - a[1])));
      for (int k = 0; k <= steps; ++k) {
        const double t = double(k) / steps;
        const int c = int(std::floor(a[0] + t * (b[0] - a[0])));
        const int r = int(std::floor(a[1] + t * (b[1] - a[1])));
        touched[size_t(r - r0) * size_t(w) + size_t(c - c0)] = 1;
      }
    }
  const std::vector<uint8_t> under = dilate(touched, w, h);
  float lowest = INFINITY;
  for (int r = r0; r <= r1; ++r)
    for (int c = c0; c <= c1; ++c)
      if (under[size_t(r - r0) * size_t(w) + size_t(c - c0)]) {
        const float z = dem.at(c, r);
        if (z < lowest) lowest = z;  // NaN compares false: skipped
      }
  if (std::isinf(lowest)) return std::nullopt;
  return lowest;
}

}  // namespace maquette::structures
