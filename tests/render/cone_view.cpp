#include "cone_view.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "cone_dem.h"

namespace maquette::test {

Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const Vec& a) { return std::sqrt(dot(a, a)); }

namespace {
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
}  // namespace

ConeView::ConeView(double eye_lon, double eye_lat, double eye_height)
    : enu_(eye_lon, eye_lat, eye_height), axis_(cone_axis()) {}

Vec ConeView::at(double azimuth, double r) const {
  const auto [lon, lat] =
      lonlat_(axis_[0] + r * std::sin(azimuth), axis_[1] + r * std::cos(azimuth));
  return enu_({lon, lat}, cone_height(r * std::sin(azimuth), r * std::cos(azimuth)));
}

// ((B - A) x B') . (E - A), E the eye (the origin).
double ConeView::tangency(double phi) const {
  const double h = 1e-4;
  const Vec a = apex(), b = at(phi, kConeRadius);
  const Vec db = sub(at(phi + h, kConeRadius), at(phi - h, kConeRadius));
  return dot(cross(sub(b, a), db), sub(Vec{0, 0, 0}, a));
}

// Sign changes of the tangency, then bisection.
std::vector<double> ConeView::tangent_azimuths() const {
  std::vector<double> roots;
  const int steps = 3600;
  for (int k = 0; k < steps; ++k) {
    double lo = 2 * std::numbers::pi * k / steps, hi = 2 * std::numbers::pi * (k + 1) / steps;
    if ((tangency(lo) > 0) == (tangency(hi) > 0)) continue;
    for (int it = 0; it < 60; ++it) {
      const double mid = 0.5 * (lo + hi);
      ((tangency(mid) > 0) == (tangency(lo) > 0) ? lo : hi) = mid;
    }
    roots.push_back(0.5 * (lo + hi));
  }
  EXPECT_EQ(roots.size(), 2u);
  return roots;
}

}  // namespace maquette::test
