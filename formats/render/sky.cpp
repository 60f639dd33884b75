#include "render/sky.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>

#include "core/round_half_away.h"

namespace maquette {
namespace {

using Bytes = std::array<uint8_t, 3>;

// Columns a < c < b of a row from the colours of a and b (written), halving (a, b) until the
// ends of each piece agree.
template <typename ColourAt>
void fill_runs(int a, int b, const Bytes& ca, const Bytes& cb, const ColourAt& at, uint8_t* rgb) {
  if (b - a < 2) return;
  if (ca == cb) {
    for (int c = a + 1; c < b; ++c) std::memcpy(rgb + 3 * size_t(c), ca.data(), 3);
    return;
  }
  const int m = a + (b - a) / 2;
  const Bytes cm = at(m);
  std::memcpy(rgb + 3 * size_t(m), cm.data(), 3);
  fill_runs(a, m, ca, cm, at, rgb);
  fill_runs(m, b, cm, cb, at, rgb);
}

}  // namespace

std::array<uint8_t, 3> sky_colour(const PinholeCamera& camera, double x, double y) {
  const Vec3d ray = camera.ray(x, y);
  const double elevation = std::atan2(ray[2], std::hypot(ray[0], ray[1]));
  const double t = std::clamp(elevation / (30 * std::numbers::pi / 180), 0.0, 1.0);
  Bytes out;
  for (size_t k = 0; k < 3; ++k)
    out[k] = uint8_t(round_half_away(kHazeColour[k] + (kZenithColour[k] - kHazeColour[k]) * t));
  return out;
}

void sky_row(const PinholeCamera& camera, int row, uint8_t* rgb) {
  const int w = camera.spec().width;
  auto at = [&](int col) { return sky_colour(camera, col + 0.5, row + 0.5); };
  // The sides: columns whose centre is left of the picture's centre (or on it), and the others.
  const int last_left = (w - 1) / 2;
  for (const auto [first, last] : {std::array{0, last_left}, std::array{last_left + 1, w - 1}}) {
    if (first > last) continue;
    const Bytes a = at(first), b = at(last);
    std::memcpy(rgb + 3 * size_t(first), a.data(), 3);
    std::memcpy(rgb + 3 * size_t(last), b.data(), 3);
    fill_runs(first, last, a, b, at, rgb);
  }
}

}  // namespace maquette
