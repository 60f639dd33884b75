// The true geometry of a tile with a 1-pixel halo: for each pixel, its position on the WGS84
// ellipsoid (core/halo.h pixel_source + pixel_centre, so halo pixels from a turned face sit where
// they really are), as ECEF, and its local east/north unit vectors. rHEALPix pixels are
// equal-area but not conformal, so operators that need metric neighbour offsets (terrain.derive,
// the climate operators) measure them here instead of assuming a regular spacing. Built once per
// tile: (size + 2)^2 inverse projections.
#pragma once

#include <vector>

#include "core/ecef.h"
#include "core/grid.h"

namespace maquette {

// Metres east and north in a pixel's tangent plane.
struct EastNorth {
  double east = 0, north = 0;
};

class TileFrame {
 public:
  TileFrame(const Grid& grid, CellId cell, int size);

  // Pixel (col, row), -1 <= col, row <= size, has a position (false beyond one face width).
  bool known(int col, int row) const { return pixel(col, row).known; }
  LonLat position(int col, int row) const { return pixel(col, row).position; }
  const Vec3& ecef(int col, int row) const { return pixel(col, row).ecef; }

  // The ECEF vector `d` (metres) in the tangent plane of pixel (col, row).
  EastNorth tangent(int col, int row, const Vec3& d) const;

 private:
  struct Pixel {
    LonLat position;
    Vec3 ecef{};
    Vec3 east{}, north{};
    bool known = false;
  };
  const Pixel& pixel(int col, int row) const {
    return pixels_[size_t(row + 1) * size_t(size_ + 2) + size_t(col + 1)];
  }

  int size_;
  std::vector<Pixel> pixels_;  // (size + 2)^2, halo included
};

}  // namespace maquette
