#include "terrain_slope.h"

#include <cmath>
#include <numbers>
#include <string>

#include "clone.h"
#include "core/error.h"

namespace maquette::synthesis {
namespace {

using Matrix = std::array<double, 4>;  // row-major {a, b, c, d}

Matrix product(const Matrix& m, const Matrix& n) {
  return {m[0] * n[0] + m[1] * n[2], m[0] * n[1] + m[1] * n[3], m[2] * n[0] + m[3] * n[2],
          m[2] * n[1] + m[3] * n[3]};
}

Matrix inverse(const Matrix& m) {
  const double det = m[0] * m[3] - m[1] * m[2];
  return {m[3] / det, -m[1] / det, -m[2] / det, m[0] / det};
}

// Sample offsets (col, row) to ground metres (east, south).
Matrix to_ground(const SampleFrame& f) { return {f.column[0], f.row[0], f.column[1], f.row[1]}; }

}  // namespace

std::array<double, 2> region_gradient(const std::vector<float>& heights, int width, int height,
                                      const std::vector<uint8_t>& region, int dx, int dy,
                                      const char* what) {
  const size_t n = size_t(width) * height;
  if (heights.size() != n || region.size() != n) {
    throw Error(std::string(what) + ": the heights and the region differ from " +
                std::to_string(width) + " x " + std::to_string(height) + " samples");
  }
  const auto at = [&](int x, int y) { return heights[size_t(y) * width + x]; };
  double gx = 0, gy = 0;
  size_t count = 0;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      if (region[size_t(y) * width + x] == 0) continue;
      const int u = x + dx, v = y + dy;
      if (u < 1 || v < 1 || u >= width - 1 || v >= height - 1) continue;
      const double ex = at(u + 1, v) - at(u - 1, v), ey = at(u, v + 1) - at(u, v - 1);
      if (!std::isfinite(ex) || !std::isfinite(ey)) continue;
      gx += ex, gy += ey, ++count;
    }
  }
  if (count == 0) throw Error(std::string(what) + ": no known heights under the region");
  return {gx / (2 * double(count)), gy / (2 * double(count))};
}

GroundSlope ground_slope(std::array<double, 2> gradient, const SampleFrame& frame) {
  // The ground gradient g satisfies J^T g = the per-sample gradient (J: samples to ground).
  const Matrix j = to_ground(frame);
  const Matrix t = inverse({j[0], j[2], j[1], j[3]});
  const double east = t[0] * gradient[0] + t[1] * gradient[1];
  const double south = t[2] * gradient[0] + t[3] * gradient[1];
  return {std::atan(std::hypot(east, south)) * 180 / std::numbers::pi,
          std::atan2(south, east) * 180 / std::numbers::pi};
}

std::array<double, 4> slope_resize(GroundSlope from, const SampleFrame& from_frame, GroundSlope to,
                                   const SampleFrame& to_frame) {
  const Matrix ground = product(foreshortening(0, to.slope_deg, to.aspect_deg),
                                foreshortening(from.slope_deg, 0, from.aspect_deg));
  return product(inverse(to_ground(to_frame)), product(ground, to_ground(from_frame)));
}

}  // namespace maquette::synthesis
