#include "gltf/local_frame.h"

namespace maquette {

LocalFrame::LocalFrame(LonLat origin)
    : origin_(origin),
      origin_ecef_(ecef(origin)),
      axes_{east_unit(origin), north_unit(origin), up_unit(origin)} {}

Vec3 LocalFrame::to_gltf(LonLat p, double height) const {
  const Vec3 e = ecef(p, height);
  const Vec3 d = {e[0] - origin_ecef_[0], e[1] - origin_ecef_[1], e[2] - origin_ecef_[2]};
  auto dot = [&d](const Vec3& a) { return a[0] * d[0] + a[1] * d[1] + a[2] * d[2]; };
  return {dot(axes_[0]), dot(axes_[2]), -dot(axes_[1])};
}

std::array<double, 16> LocalFrame::enu_to_ecef() const {
  std::array<double, 16> m{};
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) m[size_t(4 * c + r)] = axes_[size_t(c)][size_t(r)];
  for (int r = 0; r < 3; ++r) m[size_t(12 + r)] = origin_ecef_[size_t(r)];
  m[15] = 1;
  return m;
}

}  // namespace maquette
