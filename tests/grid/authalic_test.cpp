// The authalic latitude series against GeographicLib and against the closed form in long
// double (GeographicLib works in double and degrees, so is itself off by up to ~4e-16 rad).
#include "rhealpix/authalic.h"

#include <gtest/gtest.h>

#include <GeographicLib/Constants.hpp>
#include <GeographicLib/Ellipsoid.hpp>

namespace maquette {
namespace {

constexpr double kDeg = M_PI / 180;

TEST(Authalic, MatchesGeographicLib) {
  const AuthalicLatitude series;
  const GeographicLib::Ellipsoid wgs84(GeographicLib::Constants::WGS84_a(),
                                       GeographicLib::Constants::WGS84_f());
  for (int i = -9000; i <= 9000; ++i) {
    const double deg = i * 0.01;
    ASSERT_NEAR(series.authalic(deg * kDeg), wgs84.AuthalicLatitude(deg) * kDeg, 1e-15) << deg;
    ASSERT_NEAR(series.geodetic(deg * kDeg), wgs84.InverseAuthalicLatitude(deg) * kDeg, 1e-15)
        << deg;
  }
}

// q(phi) / q(pi/2) = sin beta.
long double closed_form_sin_beta(long double phi) {
  const long double f = 1 / 298.257223563L, e = std::sqrt(f * (2 - f));
  const auto q = [e](long double s) {
    return (1 - e * e) * (s / (1 - e * e * s * s) + std::atanh(e * s) / e);
  };
  return q(std::sin(phi)) / q(1);
}

// Up to 85 degrees, where the long double closed form still has a few digits to spare (near
// the poles 1 - sin beta cancels; there the tests against GeographicLib and PROJ apply).
TEST(Authalic, ExactToDoublePrecision) {
  const AuthalicLatitude series;
  for (int i = -8500; i <= 8500; ++i) {
    const double phi = i * 0.01 * kDeg;
    const long double sin_beta = closed_form_sin_beta(phi);
    const long double cos_beta = std::sqrt((1 - sin_beta) * (1 + sin_beta));
    ASSERT_NEAR(series.authalic(phi), std::asin(sin_beta), 2.3e-16) << i;
    double s = 0, c = 0;
    series.sin_cos(std::sin(phi), std::cos(phi), s, c);
    ASSERT_NEAR(s, sin_beta, 1.5e-16) << i;
    // Relative precision of cos beta near the poles is what keeps the polar faces precise.
    ASSERT_NEAR(c / cos_beta, 1, 4e-16) << i;
  }
}

TEST(Authalic, Radius) { EXPECT_NEAR(AuthalicLatitude().radius(), 6371007.180918, 1e-6); }

}  // namespace
}  // namespace maquette
