#include "local_frame.h"

#include <cmath>

#include "core/halo.h"

namespace maquette::climate {
namespace {

using Vec3 = std::array<double, 3>;

constexpr double kRad = M_PI / 180;

// WGS84 ECEF position (metres) of a point on the ellipsoid.
Vec3 ecef(LonLat p) {
  constexpr double a = 6378137.0, f = 1 / 298.257223563, e2 = f * (2 - f);
  const double lat = p.lat * kRad, lon = p.lon * kRad;
  const double n = a / std::sqrt(1 - e2 * std::sin(lat) * std::sin(lat));
  return {n * std::cos(lat) * std::cos(lon), n * std::cos(lat) * std::sin(lon),
          n * (1 - e2) * std::sin(lat)};
}

Step project(const Vec3& d, LonLat p) {
  const double lat = p.lat * kRad, lon = p.lon * kRad;
  const Vec3 east{-std::sin(lon), std::cos(lon), 0};
  const Vec3 north{-std::sin(lat) * std::cos(lon), -std::sin(lat) * std::sin(lon), std::cos(lat)};
  return {d[0] * east[0] + d[1] * east[1] + d[2] * east[2],
          d[0] * north[0] + d[1] * north[1] + d[2] * north[2]};
}

}  // namespace

LocalFrames::LocalFrames(const Grid& grid, CellId cell, int size)
    : size_(size), frames_(size_t(size) * size_t(size)) {
  const int level = cell.level() + log2_tile_size(size);
  const int stride = size + 2;
  std::vector<LonLat> where(size_t(stride) * stride);
  std::vector<char> known(where.size(), 0);
  for (int row = -1; row <= size; ++row)
    for (int col = -1; col <= size; ++col) {
      const auto source = pixel_source(grid, cell, size, col, row);
      if (!source) continue;
      const size_t i = size_t(row + 1) * stride + size_t(col + 1);
      where[i] = pixel_centre(grid, *source, level);
      known[i] = 1;
    }
  const auto index = [&](int col, int row) { return size_t(row + 1) * stride + size_t(col + 1); };
  for (int row = 0; row < size; ++row)
    for (int col = 0; col < size; ++col) {
      const size_t l = index(col - 1, row), r = index(col + 1, row);
      const size_t u = index(col, row - 1), d = index(col, row + 1);
      if (!known[l] || !known[r] || !known[u] || !known[d]) continue;
      const LonLat centre = where[index(col, row)];
      const Vec3 pl = ecef(where[l]), pr = ecef(where[r]), pu = ecef(where[u]), pd = ecef(where[d]);
      PixelFrame& f = frames_[size_t(row) * size + col];
      f.lat = centre.lat;
      f.col = project({(pr[0] - pl[0]) / 2, (pr[1] - pl[1]) / 2, (pr[2] - pl[2]) / 2}, centre);
      f.row = project({(pd[0] - pu[0]) / 2, (pd[1] - pu[1]) / 2, (pd[2] - pu[2]) / 2}, centre);
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

double bilinear(const Tile<float>& tile, double x, double y) {
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

}  // namespace maquette::climate
