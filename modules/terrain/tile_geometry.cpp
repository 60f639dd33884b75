#include "tile_geometry.h"

#include <GeographicLib/Geocentric.hpp>
#include <cmath>

#include "core/halo.h"
#include "core/tile.h"

namespace maquette::terrain {
namespace {

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

double radians(double degrees) { return degrees * (M_PI / 180); }

}  // namespace

Vec3 ecef(LonLat p) {
  Vec3 r;
  GeographicLib::Geocentric::WGS84().Forward(p.lat, p.lon, 0, r[0], r[1], r[2]);
  return r;
}

Vec3 east_unit(LonLat p) {
  const double lon = radians(p.lon);
  return {-std::sin(lon), std::cos(lon), 0};
}

Vec3 north_unit(LonLat p) {
  const double lon = radians(p.lon), lat = radians(p.lat);
  return {-std::sin(lat) * std::cos(lon), -std::sin(lat) * std::sin(lon), std::cos(lat)};
}

Vec3 up_unit(LonLat p) {
  const double lon = radians(p.lon), lat = radians(p.lat);
  return {std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)};
}

TileGeometry::TileGeometry(const Grid& grid, CellId cell, int size)
    : size_(size), pixels_(size_t(size + 2) * size_t(size + 2)) {
  const int pixel_level = cell.level() + log2_tile_size(size);
  for (int row = -1; row <= size; ++row)
    for (int col = -1; col <= size; ++col) {
      const std::optional<FaceCoord> source = pixel_source(grid, cell, size, col, row);
      if (!source) continue;
      const LonLat p = pixel_centre(grid, *source, pixel_level);
      pixels_[(row + 1) * (size + 2) + col + 1] = {ecef(p), east_unit(p), north_unit(p), true};
    }
}

bool TileGeometry::neighbourhood(int col, int row, Neighbourhood& out) const {
  const Pixel& centre = pixel(col, row);
  for (int i = 0; i < 9; ++i) {
    const Pixel& p = pixel(col + i % 3 - 1, row + i / 3 - 1);
    if (!p.valid) return false;
    const Vec3 d{p.ecef[0] - centre.ecef[0], p.ecef[1] - centre.ecef[1],
                 p.ecef[2] - centre.ecef[2]};
    out.east[i] = dot(d, centre.east);
    out.north[i] = dot(d, centre.north);
  }
  return true;
}

}  // namespace maquette::terrain
