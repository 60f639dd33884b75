#include "terrain_slope.h"

#include <cmath>
#include <numbers>
#include <string>

#include "clone.h"
#include "core/error.h"

namespace maquette::synthesis {

GroundSlope region_slope(const std::vector<float>& heights, int width, int height, double spacing_m,
                         const std::vector<uint8_t>& region, int dx, int dy, const char* what) {
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
  gx /= 2 * spacing_m * double(count), gy /= 2 * spacing_m * double(count);
  return {std::atan(std::hypot(gx, gy)) * 180 / std::numbers::pi,
          std::atan2(gy, gx) * 180 / std::numbers::pi};
}

std::array<double, 4> slope_resize(GroundSlope from, GroundSlope to) {
  const auto [a, b, c, d] = foreshortening(from.slope_deg, 0, from.aspect_deg);
  const auto [e, f, g, h] = foreshortening(0, to.slope_deg, to.aspect_deg);
  // (e f; g h) (a b; c d): first off the source's slope, then onto the destination's.
  return {e * a + f * c, e * b + f * d, g * a + h * c, g * b + h * d};
}

}  // namespace maquette::synthesis
