#include "local_frame.h"

#include <cmath>

namespace maquette::climate {
namespace {

constexpr double kRad = M_PI / 180;

}  // namespace

LocalFrames::LocalFrames(const Grid& grid, CellId cell, int size)
    : size_(size), frames_(size_t(size) * size_t(size)) {
  const TileFrame tile(grid, cell, size);
  // Half the ECEF difference of the two neighbours along an axis: a central difference.
  const auto half = [](const Vec3& a, const Vec3& b) {
    return Vec3{(b[0] - a[0]) / 2, (b[1] - a[1]) / 2, (b[2] - a[2]) / 2};
  };
  for (int row = 0; row < size; ++row)
    for (int col = 0; col < size; ++col) {
      if (!tile.known(col - 1, row) || !tile.known(col + 1, row) || !tile.known(col, row - 1) ||
          !tile.known(col, row + 1))
        continue;
      PixelFrame& f = frames_[size_t(row) * size + col];
      f.lat = tile.position(col, row).lat;
      f.col = tile.tangent(col, row, half(tile.ecef(col - 1, row), tile.ecef(col + 1, row)));
      f.row = tile.tangent(col, row, half(tile.ecef(col, row - 1), tile.ecef(col, row + 1)));
      f.valid = true;
    }
}

bool LocalFrames::gradient(const Tile<float>& dem, int col, int row, Gradient& out) const {
  const PixelFrame& f = at(col, row);
  if (!f.valid) return false;
  const double dz_col = (double(dem.at(col + 1, row)) - dem.at(col - 1, row)) / 2;
  const double dz_row = (double(dem.at(col, row + 1)) - dem.at(col, row - 1)) / 2;
  if (std::isnan(dz_col) || std::isnan(dz_row)) return false;
  // dz_col = g . col_step, dz_row = g . row_step: a 2x2 system for g.
  const double det = f.col.east * f.row.north - f.col.north * f.row.east;
  out.east = (dz_col * f.row.north - dz_row * f.col.north) / det;
  out.north = (f.col.east * dz_row - f.row.east * dz_col) / det;
  return true;
}

March march(const PixelFrame& f, double azimuth_deg) {
  const double e = std::sin(azimuth_deg * kRad), n = std::cos(azimuth_deg * kRad);
  // Pixel offsets (per metre) of the unit direction: solve col_step * c + row_step * r = (e, n).
  const double det = f.col.east * f.row.north - f.col.north * f.row.east;
  const double c = (e * f.row.north - n * f.row.east) / det;
  const double r = (f.col.east * n - f.col.north * e) / det;
  const double longest = std::max(std::abs(c), std::abs(r));
  return {c / longest, r / longest, 1 / longest};
}

}  // namespace maquette::climate
