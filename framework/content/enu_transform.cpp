#include "content/enu_transform.h"

#include <cmath>

#include "core/ecef.h"

namespace maquette {
namespace {

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

}  // namespace

EnuTransform::EnuTransform(const EnuOrigin& from, const EnuOrigin& to) {
  const LonLat f{from.lon, from.lat}, t{to.lon, to.lat};
  const std::array<Vec3, 3> from_axes{east_unit(f), north_unit(f), up_unit(f)};
  const std::array<Vec3, 3> to_axes{east_unit(t), north_unit(t), up_unit(t)};
  const Vec3 from_ecef = ecef(f, from.height), to_ecef = ecef(t, to.height);
  const Vec3 shift{from_ecef[0] - to_ecef[0], from_ecef[1] - to_ecef[1], from_ecef[2] - to_ecef[2]};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) rotation_[i][j] = dot(to_axes[i], from_axes[j]);
    translation_[i] = dot(to_axes[i], shift);
  }
}

std::array<double, 3> EnuTransform::direction(double x, double y, double z) const {
  std::array<double, 3> out;
  for (int i = 0; i < 3; ++i)
    out[i] = rotation_[i][0] * x + rotation_[i][1] * y + rotation_[i][2] * z;
  return out;
}

std::array<double, 4> EnuTransform::rotation(double x, double y, double z, double w) const {
  // The frames' rotation as a quaternion (Shepperd's method: the largest of the four
  // candidates keeps the division well away from zero).
  const auto& r = rotation_;
  const double trace = r[0][0] + r[1][1] + r[2][2];
  double a, b, c, d;  // x, y, z, w
  if (trace >= r[0][0] && trace >= r[1][1] && trace >= r[2][2]) {
    d = 0.5 * std::sqrt(1 + trace);
    a = (r[2][1] - r[1][2]) / (4 * d), b = (r[0][2] - r[2][0]) / (4 * d);
    c = (r[1][0] - r[0][1]) / (4 * d);
  } else if (r[0][0] >= r[1][1] && r[0][0] >= r[2][2]) {
    a = 0.5 * std::sqrt(1 + r[0][0] - r[1][1] - r[2][2]);
    b = (r[0][1] + r[1][0]) / (4 * a), c = (r[0][2] + r[2][0]) / (4 * a);
    d = (r[2][1] - r[1][2]) / (4 * a);
  } else if (r[1][1] >= r[2][2]) {
    b = 0.5 * std::sqrt(1 - r[0][0] + r[1][1] - r[2][2]);
    a = (r[0][1] + r[1][0]) / (4 * b), c = (r[1][2] + r[2][1]) / (4 * b);
    d = (r[0][2] - r[2][0]) / (4 * b);
  } else {
    c = 0.5 * std::sqrt(1 - r[0][0] - r[1][1] + r[2][2]);
    a = (r[0][2] + r[2][0]) / (4 * c), b = (r[1][2] + r[2][1]) / (4 * c);
    d = (r[1][0] - r[0][1]) / (4 * c);
  }
  // (a, b, c, d) * (x, y, z, w): the instance's rotation first, then the frames'.
  return {d * x + a * w + b * z - c * y, d * y - a * z + b * w + c * x,
          d * z + a * y - b * x + c * w, d * w - a * x - b * y - c * z};
}

std::array<double, 3> EnuTransform::point(double x, double y, double z) const {
  auto out = direction(x, y, z);
  for (int i = 0; i < 3; ++i) out[i] += translation_[i];
  return out;
}

std::array<double, 16> EnuTransform::matrix() const {
  std::array<double, 16> m{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) m[4 * i + j] = rotation_[i][j];
    m[4 * i + 3] = translation_[i];
  }
  m[15] = 1;
  return m;
}

}  // namespace maquette
