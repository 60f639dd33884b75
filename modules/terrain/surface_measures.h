// Terrain measures from a local gradient (and Hessian) in the east-north-up frame.
#pragma once

#include <array>

#include "surface_fit.h"

namespace maquette::terrain {

double slope_degrees(Gradient g);
// Direction the slope faces (steepest descent), degrees clockwise from north in [0, 360);
// NaN where the gradient is exactly zero.
double aspect_degrees(Gradient g);
// Unit upward normal of the surface, east-north-up components.
std::array<double, 3> normal_enu(Gradient g);

struct Light {
  double azimuth_deg = 315;  // direction the light comes from, clockwise from north
  double altitude_deg = 45;  // above the horizon
  double z_factor = 1;       // vertical exaggeration
};
// gdaldem's convention: 1 + 254 * max(0, cos(incidence)), so 0 stays free for nodata.
double hillshade(Gradient g, const Light& light);

// Profile curvature (1/m) of a fitted quadratic: the normal curvature of the surface along the
// steepest-descent direction, -(p^2 r + 2pqs + q^2 t) / ((p^2 + q^2) (1 + p^2 + q^2)^(3/2)) with
// (p, q) its gradient and (r, s, t) its Hessian. Positive where the slope steepens downhill
// (convex, e.g. a hilltop's shoulder), negative where it flattens (concave, e.g. a valley
// floor); NaN where the gradient is exactly zero.
double profile_curvature(const Quadratic& f);

}  // namespace maquette::terrain
