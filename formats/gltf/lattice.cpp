#include "gltf/lattice.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace maquette {

Lattice Lattice::for_extent(double max_extent, int bits) {
  const double steps = double((1 << bits) - 2);  // one step is kept for snapping
  return {std::exp2(std::ceil(std::log2(std::max(max_extent, 1e-3) / steps))), bits};
}

float Lattice::range() const { return float(step * double((1 << bits) - 1)); }

void Lattice::rebase(TerrainMesh& mesh) const {
  std::array<double, 3> lo;
  lo.fill(std::numeric_limits<double>::max());
  std::vector<double>& p = mesh.positions;
  for (size_t i = 0; i < p.size(); ++i) {
    // A function of the position in the export's frame alone, so that cells sharing a vertex
    // snap it alike.
    p[i] = std::round((mesh.offset[i % 3] + p[i]) / step) * step;
    lo[i % 3] = std::min(lo[i % 3], p[i]);
  }
  if (p.empty()) return;
  for (size_t i = 0; i < p.size(); ++i) p[i] -= lo[i % 3];  // exact: both are multiples of step
  mesh.offset = {lo[0], lo[1], lo[2]};
}

double extent(const std::vector<double>& positions) {
  std::array<double, 3> lo, hi;
  lo.fill(std::numeric_limits<double>::max());
  hi.fill(std::numeric_limits<double>::lowest());
  for (size_t i = 0; i < positions.size(); ++i) {
    lo[i % 3] = std::min(lo[i % 3], positions[i]);
    hi[i % 3] = std::max(hi[i % 3], positions[i]);
  }
  double e = 0;
  for (int k = 0; k < 3; ++k) e = std::max(e, hi[size_t(k)] - lo[size_t(k)]);
  return e;
}

}  // namespace maquette
