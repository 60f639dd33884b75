#include "loop_marking.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace maquette::deform {
namespace {

double cross(const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
  return u.x() * v.y() - u.y() * v.x();
}

double point_segment_distance(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                              const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double length2 = ab.squaredNorm();
  const double s = length2 > 0.0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (a + s * ab - p).norm();
}

bool segments_cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                    const Eigen::Vector2d& d) {
  const double abc = cross(b - a, c - a);
  const double abd = cross(b - a, d - a);
  const double cda = cross(d - c, a - c);
  const double cdb = cross(d - c, b - c);
  return ((abc > 0.0) != (abd > 0.0)) && ((cda > 0.0) != (cdb > 0.0));
}

double segment_segment_distance(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                const Eigen::Vector2d& c, const Eigen::Vector2d& d) {
  if (segments_cross(a, b, c, d)) return 0.0;
  return std::min({point_segment_distance(a, c, d), point_segment_distance(b, c, d),
                   point_segment_distance(c, a, b), point_segment_distance(d, a, b)});
}

bool inside_triangle(const Eigen::Vector2d& p, const std::array<Eigen::Vector2d, 3>& corner) {
  const double area = cross(corner[1] - corner[0], corner[2] - corner[0]);
  double sides[3];
  for (std::size_t i = 0; i < 3; ++i) {
    sides[i] = cross(corner[(i + 1) % 3] - corner[i], p - corner[i]) * area;
  }
  return sides[0] >= 0.0 && sides[1] >= 0.0 && sides[2] >= 0.0;
}

}  // namespace

std::vector<bool> triangles_near_polyline(const TriangleMesh& mesh,
                                          std::span<const Eigen::Vector2d> polyline,
                                          double distance) {
  if (polyline.size() < 2) {
    throw std::invalid_argument("feature polyline: " + std::to_string(polyline.size()) +
                                " points, at least 2 needed");
  }
  if (!(distance >= 0.0) || !std::isfinite(distance)) {
    throw std::invalid_argument("feature distance must be finite and >= 0, got " +
                                std::to_string(distance));
  }
  // Triangles whose bounding box is farther than `distance` from the polyline's are not near.
  Eigen::AlignedBox2d reach;
  for (const auto& p : polyline) reach.extend(p);
  reach.min().array() -= distance;
  reach.max().array() += distance;
  std::vector<bool> near(mesh.triangles.size(), false);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    std::array<Eigen::Vector2d, 3> corner;
    Eigen::AlignedBox2d box;
    for (std::size_t i = 0; i < 3; ++i) {
      corner[i] = mesh.vertices.row(mesh.triangles[t][i]).head<2>().transpose();
      box.extend(corner[i]);
    }
    if (!box.intersects(reach)) continue;
    double closest = inside_triangle(polyline[0], corner) ? 0.0 : distance + 1.0;
    for (std::size_t s = 0; s + 1 < polyline.size() && closest > distance; ++s) {
      for (std::size_t i = 0; i < 3; ++i) {
        closest = std::min(closest, segment_segment_distance(polyline[s], polyline[s + 1],
                                                             corner[i], corner[(i + 1) % 3]));
      }
    }
    near[t] = closest <= distance;
  }
  return near;
}

}  // namespace maquette::deform
