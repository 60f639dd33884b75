#include "sun.h"

#include <algorithm>
#include <cmath>

namespace maquette::climate {
namespace {

double day_angle(int day) { return 2 * M_PI * (day - 1) / 365; }

constexpr int kAirMassSamples = 4097;  // of the table, in the solar altitude's sine

// Relative optical air mass at sea level with the sun at altitude sine `up`, finite at the
// horizon: Kasten & Young (1989) in the zenith angle, or r.sun's form of it in the altitude
// corrected for refraction.
double sea_level_air_mass(Atmosphere atmosphere, double up) {
  if (atmosphere == Atmosphere::Transmissivity) {
    const double zenith_deg = std::acos(up) * 180 / M_PI;
    return 1 / (up + 0.50572 * std::pow(96.07995 - zenith_deg, -1.6364));
  }
  const double h = std::asin(up);
  const double refraction =
      0.061359 * (0.1594 + h * (1.123 + 0.065656 * h)) / (1 + h * (28.9344 + 277.3971 * h));
  const double apparent = h + refraction;
  return 1 / (std::sin(apparent) + 0.50572 * std::pow(apparent * 180 / M_PI + 6.07995, -1.6364));
}

// Rayleigh optical thickness at relative air mass m (Kasten 1996, as in r.sun).
double rayleigh_thickness(double m) {
  if (m > 20) return 1 / (10.4 + 0.718 * m);
  return 1 / (6.6296 + m * (1.7513 + m * (-0.1202 + m * (0.0065 - m * 0.00013))));
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

double Horizon::towards(double azimuth) const {
  const int n = int(angles.size());
  double x = azimuth / (2 * M_PI) * n;
  x -= std::floor(x / n) * n;
  const int i = int(x) % n;
  const double t = x - std::floor(x);
  return (1 - t) * angles[size_t(i)] + t * angles[size_t((i + 1) % n)];
}

SolarModel::SolarModel(const SolarOptions& options)
    : options_(options),
      sun_(sun_samples(options)),
      air_mass_(kAirMassSamples),
      log_transmissivity_(std::log(options.transmissivity)) {
  for (int i = 0; i < kAirMassSamples; ++i)
    air_mass_[size_t(i)] =
        sea_level_air_mass(options.atmosphere, double(i) / (kAirMassSamples - 1));
}

double SolarModel::air_mass(double up) const {
  const double x = up * (kAirMassSamples - 1);
  const int i = std::min(int(x), kAirMassSamples - 2);
  const double t = x - i;
  return (1 - t) * air_mass_[size_t(i)] + t * air_mass_[size_t(i) + 1];
}

double SolarModel::beam(double up, double pressure) const {
  const double m = pressure * air_mass(up);
  if (options_.atmosphere == Atmosphere::Linke)
    return std::exp(-0.8662 * options_.linke_turbidity * m * rayleigh_thickness(m));
  return options_.transmissivity == 1 ? 1 : std::exp(log_transmissivity_ * m);
}

void SolarModel::mark_directions(double lat_deg, std::vector<char>& used) const {
  const double lat = lat_deg * (M_PI / 180);
  const double sl = std::sin(lat), cl = std::cos(lat);
  const int n = int(used.size());
  for (const SunSample& s : sun_) {
    if (sl * s.sin_decl + cl * s.cos_decl_cos <= 0) continue;
    const double north = cl * s.sin_decl - sl * s.cos_decl_cos;
    double x = std::atan2(s.east, north) / (2 * M_PI) * n;  // as Horizon::towards
    x -= std::floor(x / n) * n;
    const int i = int(x) % n;
    used[size_t(i)] = used[size_t((i + 1) % n)] = 1;
  }
}

double SolarModel::radiation(double lat_deg, double grad_east, double grad_north,
                             double elevation_m, const Horizon* horizon) const {
  const double lat = lat_deg * (M_PI / 180);
  const double sl = std::sin(lat), cl = std::cos(lat);
  const double norm = 1 / std::sqrt(1 + grad_east * grad_east + grad_north * grad_north);
  const double ne = -grad_east * norm, nn = -grad_north * norm, nu = norm;
  // Standard-atmosphere pressure ratio: thinner air above sea level.
  const double pressure = std::exp(-elevation_m / 8434.5);
  const double above_all = horizon ? std::sin(horizon->highest) : -1;
  double sum = 0;
  for (const SunSample& s : sun_) {
    const double up = sl * s.sin_decl + cl * s.cos_decl_cos;
    if (up <= 0) continue;
    const double north = cl * s.sin_decl - sl * s.cos_decl_cos;
    const double incidence = s.east * ne + north * nn + up * nu;
    if (incidence <= 0) continue;
    if (up <= above_all && up <= std::sin(horizon->towards(std::atan2(s.east, north)))) continue;
    sum += s.weight * beam(up, pressure) * incidence;
  }
  return sum;
}

}  // namespace maquette::climate
