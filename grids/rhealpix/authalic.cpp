#include "authalic.h"

#include <GeographicLib/Constants.hpp>
#include <GeographicLib/Ellipsoid.hpp>
#include <cmath>
#include <numbers>

namespace maquette {
namespace {

// Discrete sine transform of f(x) - x, with f odd and f(x) - x vanishing at 0 and pi/2:
// c_k = (2/M) sum_{j=1}^{M-1} (f(x_j) - x_j) sin(2k x_j), x_j = j pi / (2M). Aliasing brings in
// c_{2M-k}, negligible for M = 32. f works in degrees, as GeographicLib does.
template <typename F>
AuthalicLatitude::Coefficients sine_series(F f) {
  constexpr int kSamples = 32;
  constexpr long double kPi = std::numbers::pi_v<long double>;
  std::array<long double, kSamples> diff{};
  for (int j = 1; j < kSamples; ++j) {
    const double x_deg = 90.0 * j / kSamples;
    diff[size_t(j)] = (static_cast<long double>(f(x_deg)) - x_deg) * kPi / 180;
  }
  AuthalicLatitude::Coefficients c{};
  for (int k = 1; k <= AuthalicLatitude::kTerms; ++k) {
    long double sum = 0;
    for (int j = 1; j < kSamples; ++j) sum += diff[size_t(j)] * std::sin(kPi * k * j / kSamples);
    c[size_t(k - 1)] = double(2 * sum / kSamples);
  }
  return c;
}

}  // namespace

AuthalicLatitude::AuthalicLatitude() {
  const GeographicLib::Ellipsoid wgs84(GeographicLib::Constants::WGS84_a(),
                                       GeographicLib::Constants::WGS84_f());
  forward_ = sine_series([&](double phi) { return wgs84.AuthalicLatitude(phi); });
  inverse_ = sine_series([&](double beta) { return wgs84.InverseAuthalicLatitude(beta); });
  radius_ = std::sqrt(wgs84.Area() / (4 * std::numbers::pi));
}

double AuthalicLatitude::authalic(double phi) const {
  return phi + series(forward_, std::sin(2 * phi), std::cos(2 * phi));
}

double AuthalicLatitude::geodetic(double beta) const {
  return beta + series(inverse_, std::sin(2 * beta), std::cos(2 * beta));
}

}  // namespace maquette
