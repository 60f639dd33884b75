#include "render/cast_shadow.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace maquette {
namespace {

constexpr double kTolerance = 0.01;  // metres: see the header

}  // namespace

CastShadow::CastShadow(const HeightGrid& grid, double azimuth_deg, double altitude_deg,
                       ShadowSampling sampling)
    : grid_(grid), sampling_(sampling) {
  const double az = azimuth_deg * std::numbers::pi / 180;
  // One step towards the sun, in columns (east) and rows (south).
  dcol_ = std::sin(az);
  drow_ = -std::cos(az);
  rise_ = grid.spacing * std::tan(altitude_deg * std::numbers::pi / 180);
  highest_ = -INFINITY;
  for (const float z : grid.z)
    if (!std::isnan(z)) highest_ = std::max(highest_, double(z));
}

double CastShadow::height(double col, double row) const {
  if (sampling_ == ShadowSampling::Nearest) {
    const auto c = std::lround(col), r = std::lround(row);
    if (c < 0 || r < 0 || c >= grid_.width || r >= grid_.height) return NAN;
    return grid_.z[size_t(r) * size_t(grid_.width) + size_t(c)];
  }
  const double c = std::floor(col), r = std::floor(row), fc = col - c, fr = row - r;
  if (c >= 0 && r >= 0 && c + 1 < grid_.width && r + 1 < grid_.height) {
    // Inside the grid: the four nodes at once (NaN when one has no data: read again below).
    const float* z = &grid_.z[size_t(r) * size_t(grid_.width) + size_t(c)];
    const float* below = z + grid_.width;
    const double top = z[0] + (z[1] - z[0]) * fc, bottom = below[0] + (below[1] - below[0]) * fc;
    const double h = top + (bottom - top) * fr;
    if (!std::isnan(h)) return h;
  }
  double sum = 0, weight = 0;
  for (int k = 0; k < 4; ++k) {
    const int cc = int(c) + (k & 1), rr = int(r) + (k >> 1);
    if (cc < 0 || rr < 0 || cc >= grid_.width || rr >= grid_.height) continue;
    const float z = grid_.z[size_t(rr) * size_t(grid_.width) + size_t(cc)];
    const double w = ((k & 1) ? fc : 1 - fc) * ((k >> 1) ? fr : 1 - fr);
    if (std::isnan(z) || w == 0) continue;
    sum += w * z;
    weight += w;
  }
  return weight > 0 ? sum / weight : NAN;
}

bool CastShadow::shadowed(double x, double y, double z) const {
  double col = (x - grid_.x0) / grid_.spacing, row = (grid_.y0 - y) / grid_.spacing;
  for (double ray = z + rise_; ray <= highest_; ray += rise_) {
    col += dcol_;
    row += drow_;
    if (col <= -1 || row <= -1 || col >= grid_.width || row >= grid_.height) return false;
    const double ground = height(col, row);
    if (ground > ray + kTolerance) return true;
  }
  return false;
}

std::vector<uint8_t> CastShadow::node_mask() const {
  std::vector<uint8_t> mask(grid_.z.size(), 0);
  tbb::parallel_for(0, grid_.height, [&](int row) {
    for (int col = 0; col < grid_.width; ++col) {
      const size_t i = size_t(row) * size_t(grid_.width) + size_t(col);
      if (!std::isnan(grid_.z[i]))
        mask[i] =
            shadowed(grid_.x0 + col * grid_.spacing, grid_.y0 - row * grid_.spacing, grid_.z[i]);
    }
  });
  return mask;
}

}  // namespace maquette
