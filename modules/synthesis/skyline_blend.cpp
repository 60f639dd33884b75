#include "skyline_blend.h"

#include <tbb/parallel_for.h>

#include <array>
#include <cmath>
#include <optional>

#include "core/srgb.h"

namespace maquette::synthesis {
namespace {

// Neighbours in blend_skyline's order: above, left, right, below, then the diagonals.
constexpr std::array<std::array<int, 2>, 8> kNeighbours = {
    {{0, -1}, {-1, 0}, {1, 0}, {0, 1}, {-1, -1}, {1, -1}, {-1, 1}, {1, 1}}};

// The first neighbour of (col, row) in the picture that `wanted` accepts, or none.
template <typename Wanted>
std::optional<size_t> first_neighbour(const PanoramaPicture& p, int col, int row, Wanted wanted) {
  for (const auto& [dc, dr] : kNeighbours) {
    const int c = col + dc, r = row + dr;
    if (c < 0 || r < 0 || c >= p.width || r >= p.height) continue;
    const size_t i = size_t(r) * size_t(p.width) + size_t(c);
    if (wanted(i)) return i;
  }
  return std::nullopt;
}

}  // namespace

void blend_skyline(const PanoramaPicture& p, bool sky_painted, PaintedPanorama& painted) {
  if (p.coverage.empty()) return;
  const std::vector<uint8_t> before = painted.rgb;
  auto sky = [&](size_t i) { return std::isnan(p.distance[i]); };
  tbb::parallel_for(0, p.height, [&](int row) {
    for (int col = 0; col < p.width; ++col) {
      const size_t i = size_t(row) * size_t(p.width) + size_t(col);
      const double c = p.coverage[i];
      if (!(c > 0 && c < 1)) continue;
      const std::optional<size_t> terrain =
          !sky(i) ? std::optional(i)
                  : first_neighbour(p, col, row, [&](size_t j) { return !sky(j); });
      const std::optional<size_t> open_sky =
          sky(i) && sky_painted ? std::optional(i) : first_neighbour(p, col, row, [&](size_t j) {
            return sky(j) && p.coverage[j] == 0;
          });
      if (!terrain || !open_sky) continue;
      for (size_t k = 0; k < 3; ++k) {
        const double t = srgb_to_linear(before[3 * *terrain + k] / 255.0);
        const double s = srgb_to_linear(before[3 * *open_sky + k] / 255.0);
        painted.rgb[3 * i + k] = linear_to_srgb_byte(c * t + (1 - c) * s);
      }
    }
  });
}

}  // namespace maquette::synthesis
