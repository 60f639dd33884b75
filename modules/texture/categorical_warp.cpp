#include "categorical_warp.h"

#include <cmath>
#include <vector>

#include "core/error.h"

namespace maquette::texture {
namespace {

struct Octave {
  double spacing, amplitude;  // input pixels
};
// The coarse octave rounds a border's corners, the fine one roughens its straight runs.
constexpr Octave kOctaves[] = {{2, 0.5}, {1, 0.25}};

// A node's value in [-1, 1]: SplitMix64's finaliser of the node and the field (column warp,
// row warp; octave).
double node_value(int64_t i, int64_t j, uint64_t field) {
  uint64_t z = uint64_t(i) * 0x9E3779B97F4A7C15ull ^ uint64_t(j) * 0xC2B2AE3D27D4EB4Full ^
               field * 0x165667B19E3779F9ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return double(z >> 11) * 0x1.0p-52 - 1;  // 53 bits: [-1, 1)
}

double fade(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }

// Value noise of `field` at (u, v) in lattice units: the nodes around it blended by the fade.
double value_noise(double u, double v, uint64_t field) {
  const double fu = std::floor(u), fv = std::floor(v);
  const int64_t i = int64_t(fu), j = int64_t(fv);
  const double wu = fade(u - fu), wv = fade(v - fv);
  const double top = node_value(i, j, field) +
                     wu * (node_value(i + 1, j, field) - node_value(i, j, field)),
               bottom = node_value(i, j + 1, field) +
                        wu * (node_value(i + 1, j + 1, field) - node_value(i, j + 1, field));
  return top + wv * (bottom - top);
}

}  // namespace

std::array<double, 2> categorical_warp(double x, double y) {
  std::array<double, 2> d{0, 0};
  for (uint64_t axis = 0; axis < 2; ++axis)
    for (uint64_t o = 0; o < std::size(kOctaves); ++o)
      d[axis] += kOctaves[o].amplitude *
                 value_noise(x / kOctaves[o].spacing, y / kOctaves[o].spacing, 2 * o + axis);
  return d;
}

void nearest_warped(const Tile<float>& tile, int64_t col0, int64_t row0, int refine, int ring,
                    Plane& out) {
  if (tile.halo() < kInputHalo)
    throw Error("texture: input tiles need a halo of " + std::to_string(kInputHalo) + " pixels");
  out.reshape(tile.size() << refine, ring);
  const double step = 1.0 / double(1 << refine);  // a target pixel in input pixels (exact)
  for (int r = -ring; r < out.size + ring; ++r) {
    // Global input pixel coordinates, exact (a face has < 2^31 input pixels a side), so that
    // every tiling reads the same input pixel.
    const double y = double(row0) + (r + 0.5) * step;
    for (int c = -ring; c < out.size + ring; ++c) {
      const double x = double(col0) + (c + 0.5) * step;
      const auto [dx, dy] = categorical_warp(x, y);
      out.at(c, r) =
          tile.at(int(int64_t(std::floor(x + dx)) - col0), int(int64_t(std::floor(y + dy)) - row0));
    }
  }
}

}  // namespace maquette::texture
