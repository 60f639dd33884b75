#include "rmf.h"

#include <cstddef>

namespace maquette::deform {
namespace {

double dot(const Vec3d& a, const Vec3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

Vec3d minus(const Vec3d& a, const Vec3d& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

// `v` reflected in the plane through the origin orthogonal to `n` (n.n = c).
Vec3d reflect(const Vec3d& v, const Vec3d& n, double c) {
  const double k = 2 * dot(n, v) / c;
  return {v[0] - k * n[0], v[1] - k * n[1], v[2] - k * n[2]};
}

}  // namespace

std::vector<Frame> rotation_minimizing_frames(const std::vector<Vec3d>& points,
                                              const std::vector<Vec3d>& tangents,
                                              const Vec3d& reference0) {
  std::vector<Frame> frames{{tangents.front(), reference0}};
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const Frame& f = frames.back();
    const Vec3d v1 = minus(points[i + 1], points[i]);
    const double c1 = dot(v1, v1);
    const Vec3d r_left = reflect(f.reference, v1, c1);
    const Vec3d t_left = reflect(f.tangent, v1, c1);
    const Vec3d v2 = minus(tangents[i + 1], t_left);
    const double c2 = dot(v2, v2);
    // The reflected tangent already is the next one: the second reflection is the identity.
    const Vec3d r = c2 > 0 ? reflect(r_left, v2, c2) : r_left;
    frames.push_back({tangents[i + 1], r});
  }
  return frames;
}

}  // namespace maquette::deform
