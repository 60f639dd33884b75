#include "test_camera.h"

#include <cmath>
#include <numbers>

namespace maquette::test {
namespace {

constexpr double kDegree = std::numbers::pi / 180;

Matrix3 multiply(const Matrix3& a, const Matrix3& b) {
  Matrix3 m{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) m[i][j] += a[i][k] * b[k][j];
  return m;
}

}  // namespace

Matrix3 TestCamera::rotation() const {
  const double h = heading * kDegree, p = -pitch * kDegree;
  // Counter-clockwise about up by the heading: the viewing azimuth becomes north.
  const Matrix3 turn{{{std::cos(h), -std::sin(h), 0}, {std::sin(h), std::cos(h), 0}, {0, 0, 1}}};
  // A level camera looking north: x east, y down, z north.
  const Matrix3 level{{{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}};
  // About the camera's x axis by minus the pitch.
  const Matrix3 tilt{{{1, 0, 0}, {0, std::cos(p), -std::sin(p)}, {0, std::sin(p), std::cos(p)}}};
  return multiply(tilt, multiply(level, turn));
}

double TestCamera::focal() const { return width * 0.5 / std::tan(fov * 0.5 * kDegree); }

std::array<double, 3> TestCamera::ray(int col, int row) const {
  const Matrix3 r = rotation();
  const double c[3] = {(col - cx()) / focal(), (row - cy()) / focal(), 1};
  std::array<double, 3> d{};
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) d[i] += r[k][i] * c[k];  // the transpose: camera -> ENU
  return d;
}

std::array<double, 2> TestCamera::project(const std::array<double, 3>& enu) const {
  const Matrix3 r = rotation();
  double c[3] = {};
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) c[i] += r[i][k] * enu[k];
  return {cx() + focal() * c[0] / c[2], cy() + focal() * c[1] / c[2]};
}

std::array<double, 3> bent(const std::array<double, 3>& p, double radius, double start,
                           double base) {
  const double d = std::hypot(p[0], p[1]);
  if (d <= start) return p;
  const double angle = (d - start) / radius, below = p[2] - (base + radius);
  const double s = start - below * std::sin(angle);
  return {p[0] / d * s, p[1] / d * s, base + radius + below * std::cos(angle)};
}

}  // namespace maquette::test
