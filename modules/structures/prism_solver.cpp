#include "prism_solver.h"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <array>
#include <cmath>

#include "core/error.h"

namespace maquette::structures {

Vec3 PinholeCamera::ray(const Vec2& pixel) const {
  return {(pixel.x() - principal.x()) / focal_px, (pixel.y() - principal.y()) / focal_px, 1.0};
}

Vec2 PinholeCamera::project(const Vec3& c) const {
  return {principal.x() + focal_px * c.x() / c.z(), principal.y() + focal_px * c.y() / c.z()};
}

namespace {

int previous(const PrismClicks& c) {
  return (c.corner + int(c.profile.size()) - 1) % int(c.profile.size());
}
int next(const PrismClicks& c) { return (c.corner + 1) % int(c.profile.size()); }

void check_clicks(const PrismClicks& c, const std::string& where) {
  const int n = int(c.profile.size());
  if (n < 3) throw Error(where + ": the profile has " + std::to_string(n) + " vertices, not >= 3");
  if (c.corner < 0 || c.corner >= n)
    throw Error(where + ": corner " + std::to_string(c.corner) + " is no profile vertex (0.." +
                std::to_string(n - 1) + ")");
  std::vector<bool> seen(size_t(n), false);
  for (const auto& [i, q] : c.more_extrusions) {
    if (i < 0 || i >= n || i == c.corner || seen[size_t(i)])
      throw Error(where + ": extrusion end of vertex " + std::to_string(i) +
                  " is no other profile vertex than the corner, or is given twice");
    seen[size_t(i)] = true;
  }
  const Vec2 p1 = c.profile[size_t(c.corner)];
  const std::array<Vec2, 3> ends{c.profile[size_t(previous(c))], c.profile[size_t(next(c))],
                                 c.extrusion};
  for (size_t i = 0; i < 3; ++i) {
    const Vec2 e = ends[i] - p1, f = ends[(i + 1) % 3] - p1;
    if (e.norm() < 1 || f.norm() < 1 ||
        std::abs(e.x() * f.y() - e.y() * f.x()) < 1e-3 * e.norm() * f.norm())
      throw Error(where +
                  ": the corner's edges are shorter than a pixel or collinear in the photo");
  }
}

// Coefficients (c0, c1) of linear polynomials and their product's (c0, c1, c2).
using Linear = std::array<double, 2>;
std::array<double, 3> times(const Linear& p, const Linear& q) {
  return {p[0] * q[0], p[0] * q[1] + p[1] * q[0], p[1] * q[1]};
}

std::vector<double> real_roots(const std::array<double, 3>& c) {
  const double scale = std::max({std::abs(c[0]), std::abs(c[1]), std::abs(c[2])});
  if (scale == 0) return {};
  if (std::abs(c[2]) < 1e-12 * scale) return {-c[0] / c[1]};
  const double disc = c[1] * c[1] - 4 * c[2] * c[0];
  if (disc < 0) return {};
  // The numerically stable pair of roots.
  const double q = -0.5 * (c[1] + std::copysign(std::sqrt(disc), c[1]));
  if (q == 0) return {0.0};
  return {q / c[2], c[0] / q};
}

// The prism's free parameters in the refinement (see solve_prism's contract).
struct Pose {
  Eigen::Matrix3d axes;     // columns: the corner's edge directions a, b and extrusion c
  Vec3 corner;              // P1 (its z stays 1: the scale)
  std::vector<Vec2> plane;  // P_i = P1 + x a + y b
  double length = 0;        // the extrusion along c
  double focal_px = 0;
};

PrismSolution to_solution(const Pose& pose, int roots) {
  PrismSolution s;
  for (const Vec2& q : pose.plane)
    s.profile.push_back(pose.corner + q.x() * pose.axes.col(0) + q.y() * pose.axes.col(1));
  s.extrusion = pose.length * pose.axes.col(2);
  s.focal_px = pose.focal_px;
  s.roots = roots;
  return s;
}

Pose to_pose(const PrismSolution& s, const PrismClicks& c) {
  Pose p;
  const Vec3 p1 = s.profile[size_t(c.corner)];
  const Vec3 a = (s.profile[size_t(previous(c))] - p1).normalized();
  const Vec3 b0 = s.profile[size_t(next(c))] - p1;
  const Vec3 b = (b0 - b0.dot(a) * a).normalized();
  p.length = s.extrusion.norm();
  const Vec3 n = a.cross(b);
  p.axes << a, b, (n.dot(s.extrusion) >= 0 ? n : Vec3(-n));
  p.corner = p1;
  for (const Vec3& q : s.profile) p.plane.emplace_back((q - p1).dot(a), (q - p1).dot(b));
  p.focal_px = s.focal_px;
  return p;
}

// The clicks' reprojection residuals (pixels) of `pose`.
Eigen::VectorXd residuals(const Pose& pose, const PrismClicks& c, const Vec2& principal) {
  const PinholeCamera cam{pose.focal_px, principal};
  const PrismSolution s = to_solution(pose, 0);
  Eigen::VectorXd r(2 * (s.profile.size() + 1 + c.more_extrusions.size()));
  int k = 0;
  const auto add = [&](const Vec3& x, const Vec2& click) {
    r.segment<2>(k) = x.z() > 0 ? Vec2(cam.project(x) - click) : Vec2(1e6, 1e6);
    k += 2;
  };
  for (size_t i = 0; i < s.profile.size(); ++i) add(s.profile[i], c.profile[i]);
  add(s.profile[size_t(c.corner)] + s.extrusion, c.extrusion);
  for (const auto& [i, q] : c.more_extrusions) add(s.profile[size_t(i)] + s.extrusion, q);
  return r;
}

// `pose` moved by the parameter step `d`: rotation (3), corner x, y (2), the free in-plane
// coordinates (the previous vertex's x, the next one's y, both of every other vertex), the
// extrusion's length, and the focal length when estimated.
Pose moved(const Pose& pose, const Eigen::VectorXd& d, const PrismClicks& c, bool focal) {
  Pose p = pose;
  const Vec3 w = d.head<3>();
  if (w.norm() > 0)
    p.axes = Eigen::AngleAxisd(w.norm(), w.normalized()).toRotationMatrix() * p.axes;
  p.corner.x() += d(3);
  p.corner.y() += d(4);
  int k = 5;
  for (int i = 0; i < int(p.plane.size()); ++i) {
    if (i == c.corner) continue;
    if (i != next(c)) p.plane[size_t(i)].x() += d(k++);
    if (i != previous(c)) p.plane[size_t(i)].y() += d(k++);
  }
  p.length += d(k++);
  if (focal) p.focal_px += d(k++);
  return p;
}

int parameter_count(const PrismClicks& c, bool focal) {
  return 5 + 2 * int(c.profile.size() - 3) + 2 + 1 + (focal ? 1 : 0);
}

// Levenberg-Marquardt on the reprojection errors, central-difference Jacobian.
Pose refine(Pose pose, const PrismClicks& c, const Vec2& principal, bool focal) {
  const int n = parameter_count(c, focal);
  Eigen::VectorXd r = residuals(pose, c, principal);
  double lambda = 1e-3;
  for (int iteration = 0; iteration < 50; ++iteration) {
    Eigen::MatrixXd jac(r.size(), n);
    for (int j = 0; j < n; ++j) {
      const double h = (focal && j == n - 1) ? 1e-3 * pose.focal_px : 1e-7;
      Eigen::VectorXd d = Eigen::VectorXd::Zero(n);
      d(j) = h;
      jac.col(j) = (residuals(moved(pose, d, c, focal), c, principal) -
                    residuals(moved(pose, -d, c, focal), c, principal)) /
                   (2 * h);
    }
    const Eigen::MatrixXd jtj = jac.transpose() * jac;
    const Eigen::VectorXd jtr = jac.transpose() * r;
    bool improved = false;
    for (int attempt = 0; attempt < 10 && !improved; ++attempt) {
      Eigen::MatrixXd a = jtj;
      a.diagonal() += lambda * jtj.diagonal().cwiseMax(1e-12);
      const Eigen::VectorXd step = -a.ldlt().solve(jtr);
      const Pose trial = moved(pose, step, c, focal);
      const Eigen::VectorXd rt = residuals(trial, c, principal);
      if (rt.squaredNorm() < r.squaredNorm()) {
        improved = true;
        const bool converged = r.squaredNorm() - rt.squaredNorm() < 1e-12 * (1 + r.squaredNorm());
        pose = trial;
        r = rt;
        lambda = std::max(lambda / 10, 1e-9);
        if (converged) return pose;
      } else {
        lambda *= 10;
      }
    }
    if (!improved) break;
  }
  return pose;
}

}  // namespace

std::vector<PrismSolution> prism_roots(const PrismClicks& c, const PinholeCamera& camera) {
  const Vec3 d1 = camera.ray(c.profile[size_t(c.corner)]);
  const Vec3 da = camera.ray(c.profile[size_t(previous(c))]);
  const Vec3 db = camera.ray(c.profile[size_t(next(c))]);
  const Vec3 dc = camera.ray(c.extrusion);
  // Eq. 9 with z1 = 1: (za da - d1).(zb db - d1) = 0 gives zb = N(za) / Db(za), likewise
  // zc = N / Dc; the third pair's equation times Db Dc is a quadratic in za.
  const Linear num{-d1.dot(d1), da.dot(d1)};
  const Linear den_b{-db.dot(d1), da.dot(db)};
  const Linear den_c{-dc.dot(d1), da.dot(dc)};
  std::array<double, 3> quadratic{};
  const auto nn = times(num, num), nc = times(num, den_c), nb = times(num, den_b),
             bc = times(den_b, den_c);
  for (size_t k = 0; k < 3; ++k)
    quadratic[k] =
        db.dot(dc) * nn[k] - db.dot(d1) * nc[k] - dc.dot(d1) * nb[k] + d1.dot(d1) * bc[k];
  std::vector<PrismSolution> out;
  for (const double za : real_roots(quadratic)) {
    const double b = den_b[0] + den_b[1] * za, cc = den_c[0] + den_c[1] * za;
    if (!(za > 0) || std::abs(b) < 1e-12 || std::abs(cc) < 1e-12) continue;
    const double n = num[0] + num[1] * za;
    const double zb = n / b, zc = n / cc;
    if (!(zb > 0) || !(zc > 0)) continue;
    const Vec3 pa = za * da, pb = zb * db;
    const Vec3 normal = (pa - d1).cross(pb - d1);
    PrismSolution s;
    bool in_front = true;
    for (size_t i = 0; i < c.profile.size(); ++i) {
      const Vec3 ray = camera.ray(c.profile[i]);
      const double t = normal.dot(d1) / normal.dot(ray);  // the ray cuts the profile's plane
      in_front = in_front && t > 0 && std::isfinite(t);
      s.profile.push_back(int(i) == c.corner ? d1 : Vec3(t * ray));
    }
    if (!in_front) continue;
    s.extrusion = zc * dc - d1;
    s.corner = c.corner;
    s.focal_px = camera.focal_px;
    out.push_back(std::move(s));
  }
  for (PrismSolution& s : out) s.roots = int(out.size());
  return out;
}

std::optional<PrismSolution> checked_root(const std::vector<PrismSolution>& roots) {
  std::optional<PrismSolution> kept;
  int passed = 0;
  for (const PrismSolution& s : roots)
    if (s.profile[size_t(s.corner)].dot(s.extrusion) > 0) ++passed, kept = s;
  if (passed != 1) return std::nullopt;
  return kept;
}

PrismSolution solve_prism(const PrismClicks& clicks, const PinholeCamera& camera,
                          const std::string& where, bool estimate_focal) {
  check_clicks(clicks, where);
  const std::vector<PrismSolution> roots = prism_roots(clicks, camera);
  const std::optional<PrismSolution> root = checked_root(roots);
  if (!root)
    throw Error(where + ": of Eq. 9's " + std::to_string(roots.size()) +
                " roots in front of the camera, " +
                (roots.empty() ? std::string("none") : "not exactly one") +
                " has the extrusion pointing away from the camera behind a visible profile: are "
                "the corner's three edges and the focal length right?");
  const int observations = 2 * int(clicks.profile.size() + 1 + clicks.more_extrusions.size());
  if (observations <= parameter_count(clicks, estimate_focal)) return *root;
  PrismSolution refined = to_solution(
      refine(to_pose(*root, clicks), clicks, camera.principal, estimate_focal), root->roots);
  refined.corner = clicks.corner;
  refined.refined = true;
  refined.residual_px2 =
      residuals(to_pose(refined, clicks), clicks, camera.principal).squaredNorm();
  return refined;
}

}  // namespace maquette::structures
