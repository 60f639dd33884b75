#include "surface_measures.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace maquette::terrain {
namespace {

constexpr double kDegrees = 180 / M_PI;

double gradient_squared(Gradient g) { return g.east * g.east + g.north * g.north; }

}  // namespace

double slope_degrees(Gradient g) { return std::atan(std::sqrt(gradient_squared(g))) * kDegrees; }

double aspect_degrees(Gradient g) {
  if (g.east == 0 && g.north == 0) return std::numeric_limits<double>::quiet_NaN();
  const double a = std::atan2(-g.east, -g.north) * kDegrees;
  return a < 0 ? a + 360 : a;
}

std::array<double, 3> normal_enu(Gradient g) {
  const double k = 1 / std::sqrt(1 + gradient_squared(g));
  return {-g.east * k, -g.north * k, k};
}

double hillshade(Gradient g, const Light& light) {
  const Gradient z{g.east * light.z_factor, g.north * light.z_factor};
  const std::array<double, 3> n = normal_enu(z);
  const double az = light.azimuth_deg / kDegrees, alt = light.altitude_deg / kDegrees;
  const double cos_incidence = n[0] * std::sin(az) * std::cos(alt) +
                               n[1] * std::cos(az) * std::cos(alt) + n[2] * std::sin(alt);
  return 1 + 254 * std::max(0.0, cos_incidence);
}

double profile_curvature(const Quadratic& f) {
  const Gradient g = f.gradient;
  const Hessian& h = f.hessian;
  const double p = g.east, q = g.north, g2 = gradient_squared(g);
  if (g2 == 0) return std::numeric_limits<double>::quiet_NaN();
  return -(p * p * h.ee + 2 * p * q * h.en + q * q * h.nn) / (g2 * std::pow(1 + g2, 1.5));
}

}  // namespace maquette::terrain
