#include "gltf/lattice.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace maquette {
namespace {

std::array<float, 3> min_corner(const std::vector<float>& p) {
  std::array<float, 3> lo;
  lo.fill(std::numeric_limits<float>::max());
  for (size_t i = 0; i < p.size(); ++i) lo[i % 3] = std::min(lo[i % 3], p[i]);
  return lo;
}

}  // namespace

Lattice Lattice::for_extent(double max_extent, int bits) {
  const double steps = double((1 << bits) - 2);  // one step is kept for the floored origin
  return {std::exp2(std::ceil(std::log2(std::max(max_extent, 1e-3) / steps))), bits};
}

std::array<float, 3> Lattice::origin(const std::vector<float>& positions) const {
  std::array<float, 3> o = min_corner(positions);
  for (float& v : o) v = float(std::floor(double(v) / step) * step);
  return o;
}

float Lattice::range() const { return float(step * double((1 << bits) - 1)); }

void Lattice::snap(std::vector<float>& positions, const std::array<float, 3>& origin) const {
  for (size_t i = 0; i < positions.size(); ++i) {
    const double o = origin[i % 3];
    positions[i] = float(o + std::round((double(positions[i]) - o) / step) * step);
  }
}

double extent(const std::vector<float>& positions) {
  const std::array<float, 3> lo = min_corner(positions);
  std::array<float, 3> hi;
  hi.fill(std::numeric_limits<float>::lowest());
  for (size_t i = 0; i < positions.size(); ++i) hi[i % 3] = std::max(hi[i % 3], positions[i]);
  double e = 0;
  for (int k = 0; k < 3; ++k) e = std::max(e, double(hi[size_t(k)]) - double(lo[size_t(k)]));
  return e;
}

}  // namespace maquette
