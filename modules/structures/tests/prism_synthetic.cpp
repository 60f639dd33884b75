#include "prism_synthetic.h"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>

#include "core/splitmix64.h"

namespace maquette::structures {
namespace {

constexpr double kPi = std::numbers::pi;

struct Random {
  uint64_t state;
  double uniform(double lo, double hi) {
    return lo + (hi - lo) * unit_interval(splitmix64_next(state));
  }
  double gaussian() {  // Box-Muller
    const double u = uniform(1e-300, 1), v = uniform(0, 2 * kPi);
    return std::sqrt(-2 * std::log(u)) * std::cos(v);
  }
};

// The outward unit normals and centres of the prism's facets: the profile (y = 0), the far cap,
// then the side of each profile edge i -> i + 1.
std::vector<std::pair<Vec3, Vec3>> facets(const std::vector<Vec3>& profile, double length) {
  Vec3 centre = Vec3::Zero();
  for (const Vec3& p : profile) centre += p / double(profile.size());
  std::vector<std::pair<Vec3, Vec3>> out{{Vec3(0, -1, 0), centre},
                                         {Vec3(0, 1, 0), centre + Vec3(0, length, 0)}};
  for (size_t i = 0; i < profile.size(); ++i) {
    const Vec3 a = profile[i], b = profile[(i + 1) % profile.size()];
    // The profile runs clockwise seen from -y (corner, up, ..., along x): outward is (-dz, 0, dx).
    const Vec3 n = Vec3(-(b.z() - a.z()), 0, b.x() - a.x()).normalized();
    out.push_back({n, (a + b) / 2 + Vec3(0, length / 2, 0)});
  }
  return out;
}

std::vector<Vec2> project(const std::vector<Vec3>& world, const SyntheticPhoto& p) {
  std::vector<cv::Point3d> object;
  for (const Vec3& w : world) object.emplace_back(w.x(), w.y(), w.z());
  cv::Mat rotation, rvec;
  cv::eigen2cv(p.rotation, rotation);
  cv::Rodrigues(rotation, rvec);
  const cv::Mat tvec =
      (cv::Mat_<double>(3, 1) << p.translation.x(), p.translation.y(), p.translation.z());
  const cv::Mat k = (cv::Mat_<double>(3, 3) << p.camera.focal_px, 0, p.camera.principal.x(), 0,
                     p.camera.focal_px, p.camera.principal.y(), 0, 0, 1);
  std::vector<cv::Point2d> image;
  cv::projectPoints(object, rvec, tvec, k, cv::noArray(), image);
  std::vector<Vec2> out;
  for (const cv::Point2d& q : image) out.emplace_back(q.x, q.y);
  return out;
}

}  // namespace

Vec3 SyntheticPhoto::to_solver_frame(const Vec3& world) const {
  const Vec3 c = rotation * world + translation;
  return c / (rotation * profile[0] + translation).z();
}

SyntheticPhoto synthetic_photo(uint64_t seed, int index, double noise_px, int more_extrusions) {
  Random rng{splitmix64_mix(seed ^ splitmix64_mix(uint64_t(index)))};
  SyntheticPhoto p;
  p.width = 1200;
  p.height = 900;
  const double w = rng.uniform(5, 30), h = rng.uniform(3, 20);
  p.length = rng.uniform(5, 40);
  switch (int(rng.uniform(0, 3))) {
    case 0:  // rectangle
      p.profile = {{0, 0, 0}, {0, 0, h}, {w, 0, h}, {w, 0, 0}};
      p.right_angles = {1, 2, 3};
      break;
    case 1:  // right trapezoid: the top shorter
      p.profile = {{0, 0, 0}, {0, 0, h}, {w * rng.uniform(0.3, 0.8), 0, h}, {w, 0, 0}};
      p.right_angles = {1};
      break;
    default:  // gabled
      p.profile = {
          {0, 0, 0}, {0, 0, h}, {w / 2, 0, h + rng.uniform(0.2, 0.6) * w}, {w, 0, h}, {w, 0, 0}};
      p.right_angles = {int(p.profile.size()) - 1};
  }
  Vec3 lo(0, 0, 0), hi(w, p.length, 0);
  for (const Vec3& q : p.profile) hi.z() = std::max(hi.z(), q.z());
  const Vec3 target = (lo + hi) / 2;
  const double radius = (hi - lo).norm() / 2;
  const size_t n = p.profile.size();
  for (int attempt = 0;; ++attempt) {
    p.camera.focal_px = rng.uniform(0.6, 2.0) * p.width;
    p.camera.principal = Vec2(p.width / 2.0, p.height / 2.0);
    const double fit = radius * p.camera.focal_px / (p.height / 2.0);
    const double azimuth = rng.uniform(0, 2 * kPi), elevation = rng.uniform(-5, 45) * kPi / 180;
    const Vec3 away(std::cos(elevation) * std::cos(azimuth),
                    std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
    const Vec3 centre = target + rng.uniform(1.1, 2.5) * fit * away;
    // Looking near the target, rolled a little.
    const Vec3 look =
        (target +
         Vec3(rng.uniform(-0.2, 0.2), rng.uniform(-0.2, 0.2), rng.uniform(-0.2, 0.2)) * radius -
         centre)
            .normalized();
    const Vec3 right = look.cross(Vec3(0, 0, 1)).normalized();
    const Vec3 down = look.cross(right);
    Eigen::Matrix3d r;
    r.row(0) = right;
    r.row(1) = down;
    r.row(2) = look;
    p.rotation = Eigen::AngleAxisd(rng.uniform(-10, 10) * kPi / 180, Vec3::UnitZ()) * r;
    p.translation = -p.rotation * centre;
    bool ok = centre.z() > 0.5;
    const auto seen_sine = [&](const Vec3& normal, const Vec3& middle) {
      return normal.dot((centre - middle).normalized());
    };
    const auto sides = facets(p.profile, p.length);
    for (const auto& [normal, middle] : sides)
      ok = ok && std::abs(seen_sine(normal, middle)) > std::sin(3 * kPi / 180);
    // The clicked profile and the wall of the corner's vertical edge face the camera, not edge-on.
    ok = ok && seen_sine(sides[0].first, sides[0].second) > std::sin(10 * kPi / 180) &&
         seen_sine(sides[2].first, sides[2].second) > std::sin(10 * kPi / 180);
    std::vector<Vec3> all = p.profile;  // then the extrusion ends, the corner's first
    for (const Vec3& q : p.profile) all.push_back(q + Vec3(0, p.length, 0));
    for (const Vec3& q : all) ok = ok && (p.rotation * q + p.translation).z() > 0;
    if (!ok) continue;
    const std::vector<Vec2> image = project(all, p);
    for (const Vec2& q : image)
      ok = ok && q.x() >= 0 && q.x() <= p.width && q.y() >= 0 && q.y() <= p.height;
    // The corner's edges (to the last vertex, vertex 1, the extrusion end) at least 50 pixels long.
    for (const size_t end : {n - 1, size_t(1), n}) ok = ok && (image[end] - image[0]).norm() >= 50;
    if (!ok) continue;
    for (const auto& [normal, middle] : sides)
      p.facet_visible.push_back(seen_sine(normal, middle) > 0);
    break;
  }
  std::vector<Vec3> clicked = p.profile;
  clicked.push_back(Vec3(0, p.length, 0));
  std::vector<int> others;
  for (int k = 0; k < more_extrusions && k < int(n) - 1; ++k) {
    const int i = k % 2 == 0 ? int(n) - 1 - k / 2 : 1 + k / 2;
    others.push_back(i);
    clicked.push_back(p.profile[size_t(i)] + Vec3(0, p.length, 0));
  }
  const std::vector<Vec2> image = project(clicked, p);
  p.exact.profile.assign(image.begin(), image.begin() + long(n));
  p.exact.corner = 0;
  p.exact.extrusion = image[n];
  for (size_t k = 0; k < others.size(); ++k)
    p.exact.more_extrusions.push_back({others[k], image[n + 1 + k]});
  p.clicks = p.exact;
  const auto noisy = [&](Vec2& q) { q += noise_px * Vec2(rng.gaussian(), rng.gaussian()); };
  for (Vec2& q : p.clicks.profile) noisy(q);
  noisy(p.clicks.extrusion);
  for (auto& [i, q] : p.clicks.more_extrusions) noisy(q);
  return p;
}

}  // namespace maquette::structures
