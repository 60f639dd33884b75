#include "content/enu_transform.h"

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
