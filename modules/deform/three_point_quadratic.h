// Lagrange's quadratic through three nodes of a pair of coordinates: how deform.features
// interpolates points along a line (line_samples.h) and samples along a row (sample_positions.h)
// from three computed ones, where the map that places them is smooth.
#pragma once

#include <array>

namespace maquette::deform {

// The quadratic through (0, f0), (x1, f1) and (x2, f2), each coordinate on its own.
// Precondition: 0 < x1 < x2.
struct ThreePointQuadratic {
  double x1, x2;
  std::array<double, 2> f0, f1, f2;

  std::array<double, 2> operator()(double x) const {
    const double l0 = (x - x1) * (x - x2) / (x1 * x2), l1 = x * (x - x2) / (x1 * (x1 - x2)),
                 l2 = x * (x - x1) / (x2 * (x2 - x1));
    return {l0 * f0[0] + l1 * f1[0] + l2 * f2[0], l0 * f0[1] + l1 * f1[1] + l2 * f2[1]};
  }
};

}  // namespace maquette::deform
