// Local least-squares fits of a height field over a 3x3 neighbourhood given by true east/north
// offsets (so they hold on sheared pixels and across face seams, where the neighbourhood is
// not a regular grid).
#pragma once

#include <array>

#include "neighbourhood.h"

namespace maquette::terrain {

using Heights = std::array<double, 9>;  // row-major 3x3, centre at index 4

struct Gradient {
  double east = 0, north = 0;  // dh/dE, dh/dN (dimensionless)
};

// h = a + g . (E, N) fitted to the 8 neighbours with Horn's weights (2 for edge neighbours,
// 1 for diagonal ones): on a regular grid this is exactly Horn's (1981) slope estimator.
Gradient fit_gradient(const Neighbourhood& n, const Heights& h);

struct Hessian {
  double ee = 0, en = 0, nn = 0;  // d2h/dE2, d2h/dEdN, d2h/dN2 (1/m)
};

// h = a + g . (E, N) + (ee E^2 + 2 en EN + nn N^2) / 2 fitted by least squares to all 9 points
// (Evans-Young style): exact for quadratic fields, whatever the neighbourhood's shape.
struct Quadratic {
  Gradient gradient;
  Hessian hessian;
};
Quadratic fit_quadratic(const Neighbourhood& n, const Heights& h);

}  // namespace maquette::terrain
