// The true geometry of a tile with a 1-pixel halo: for each pixel, its position on the WGS84
// ellipsoid (via pixel_source + pixel_centre, so halo pixels from a turned face sit where they
// really are) and its local east/north unit vectors. Built once per tile, (size + 2)^2 inverse
// projections, and shared by every output of terrain.derive.
#pragma once

#include <array>
#include <vector>

#include "core/grid.h"

namespace maquette::terrain {

using Vec3 = std::array<double, 3>;

// East-north offsets (metres, in the centre pixel's tangent plane) of a 3x3 neighbourhood,
// row-major from the top-left; index 4 is the centre (0, 0).
struct Neighbourhood {
  std::array<double, 9> east{}, north{};
};

class TileGeometry {
 public:
  TileGeometry(const Grid& grid, CellId cell, int size);

  // Neighbourhood of interior pixel (col, row); false when a neighbour has no position.
  bool neighbourhood(int col, int row, Neighbourhood& out) const;

 private:
  struct Pixel {
    Vec3 ecef{};
    Vec3 east{}, north{};
    bool valid = false;
  };
  const Pixel& pixel(int col, int row) const { return pixels_[(row + 1) * (size_ + 2) + col + 1]; }

  int size_;
  std::vector<Pixel> pixels_;  // (size + 2)^2, halo included
};

// ECEF position (metres) of a point on the WGS84 ellipsoid and its local unit vectors (up is
// the ellipsoid normal).
Vec3 ecef(LonLat p);
Vec3 east_unit(LonLat p);
Vec3 north_unit(LonLat p);
Vec3 up_unit(LonLat p);

}  // namespace maquette::terrain
