#include "sun.h"

#include <algorithm>
#include <cmath>

namespace maquette::climate {
namespace {

double day_angle(int day) { return 2 * M_PI * (day - 1) / 365; }

// Relative optical air mass at a solar elevation cosine `up` (Kasten & Young 1989), finite at
// the horizon.
double air_mass(double up) {
  const double zenith_deg = std::acos(up) * 180 / M_PI;
  return 1 / (up + 0.50572 * std::pow(96.07995 - zenith_deg, -1.6364));
}

}  // namespace

double declination(int day) {
  const double g = day_angle(day);
  return 0.006918 - 0.399912 * std::cos(g) + 0.070257 * std::sin(g) - 0.006758 * std::cos(2 * g) +
         0.000907 * std::sin(2 * g) - 0.002697 * std::cos(3 * g) + 0.00148 * std::sin(3 * g);
}

double eccentricity(int day) {
  const double g = day_angle(day);
  return 1.000110 + 0.034221 * std::cos(g) + 0.001280 * std::sin(g) + 0.000719 * std::cos(2 * g) +
         0.000077 * std::sin(2 * g);
}

std::vector<SunSample> sun_samples(const SolarOptions& o) {
  std::vector<SunSample> out;
  const int steps = int(std::lround(24 * 60 / o.minutes));
  const double hours = 24.0 / steps;
  for (int day = o.first_day; day <= o.last_day; day += o.day_step) {
    const int days = std::min(o.day_step, o.last_day - day + 1);
    const double d = declination(day);
    const double weight = o.solar_constant * eccentricity(day) * hours * days;
    for (int k = 0; k < steps; ++k) {
      const double hour_angle = (((k + 0.5) * hours) - 12) * (M_PI / 12);
      out.push_back({std::sin(d), std::cos(d) * std::cos(hour_angle),
                     -std::cos(d) * std::sin(hour_angle), weight});
    }
  }
  return out;
}

double potential_radiation(const std::vector<SunSample>& sun, const SolarOptions& o, double lat_deg,
                           double grad_east, double grad_north, double elevation_m,
                           const Horizon* horizon) {
  const double lat = lat_deg * (M_PI / 180);
  const double sl = std::sin(lat), cl = std::cos(lat);
  const double norm = 1 / std::sqrt(1 + grad_east * grad_east + grad_north * grad_north);
  const double ne = -grad_east * norm, nn = -grad_north * norm, nu = norm;
  // Standard-atmosphere pressure ratio: thinner air above sea level.
  const double pressure = std::exp(-elevation_m / 8434.5);
  const double log_tau = std::log(o.transmissivity);
  const double above_all = horizon ? std::sin(horizon->highest) : -1;
  double sum = 0;
  for (const SunSample& s : sun) {
    const double up = sl * s.sin_decl + cl * s.cos_decl_cos;
    if (up <= 0) continue;
    const double north = cl * s.sin_decl - sl * s.cos_decl_cos;
    const double incidence = s.east * ne + north * nn + up * nu;
    if (incidence <= 0) continue;
    if (up <= above_all && up <= std::sin(horizon->towards(std::atan2(s.east, north)))) continue;
    const double beam = o.transmissivity == 1 ? 1 : std::exp(log_tau * air_mass(up) * pressure);
    sum += s.weight * beam * incidence;
  }
  return sum;
}

}  // namespace maquette::climate
