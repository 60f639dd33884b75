// Bilinear sampling of a tile between its samples.
#pragma once

#include <cmath>

#include "core/tile.h"

namespace maquette {

// Channel 0 of `tile` at fractional sample coordinates (x, y): sample (c, r) is at x = c, y = r
// (a pixel's centre; halo samples at negative coordinates or beyond size() - 1). NaN outside the
// tile and its halo or where a corner is NaN.
inline double bilinear(const Tile<float>& tile, double x, double y) {
  const int h = tile.halo(), n = tile.size();
  const double fx = std::floor(x), fy = std::floor(y);
  const int c = int(fx), r = int(fy);
  if (c < -h || r < -h || c + 1 >= n + h || r + 1 >= n + h) {
    // On the last row or column exactly, no neighbour is needed.
    if (x == fx && y == fy && c >= -h && r >= -h && c < n + h && r < n + h) return tile.at(c, r);
    return std::nan("");
  }
  const double tx = x - fx, ty = y - fy;
  const double top = (1 - tx) * tile.at(c, r) + tx * tile.at(c + 1, r);
  const double bottom = (1 - tx) * tile.at(c, r + 1) + tx * tile.at(c + 1, r + 1);
  return (1 - ty) * top + ty * bottom;
}

}  // namespace maquette
