#include "render/painting_fit.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <opencv2/calib3d.hpp>
#include <unsupported/Eigen/LevenbergMarquardt>
#include <unsupported/Eigen/NumericalDiff>

#include "core/error.h"

namespace maquette {
namespace {

constexpr double kDegree = std::numbers::pi / 180;
// The residual of a point behind the eye (pixels): large, so that the solve turns the camera.
constexpr double kBehind = 1e5;

double fov_of_focal(double focal, int width) {
  return 2 * std::atan(width * 0.5 / focal) / kDegree;
}

// The unknowns as one vector, scaled so that a unit step is of the same order for each: the eye in
// kilometres in the east-north-up frame at the points' centroid, heading and pitch in radians, the
// log of the focal length (pixels) when it is fitted, and with the bend q and s, the radius being
// 100 km / q^2 and the start 1 km * s^2 (both kept in range by their squares).
// Precondition: `options` and `origin` outlive it.
class Unknowns {
 public:
  Unknowns(const EnuFrame& origin, const PaintingFitOptions& options, bool bend)
      : origin_(origin), options_(options), fit_focal_(!options.fov), bend_(bend) {}

  int size() const { return 5 + fit_focal_ + 2 * bend_; }

  // The ground's height under the eye (above the ellipsoid), the bend's base: held while
  // Levenberg-Marquardt runs (the DEM is read between runs, not at each step).
  double ground = 0;

  Eigen::VectorXd pack(const CameraSpec& camera, const ProgressiveBend& bend) const {
    Eigen::VectorXd x(size());
    const auto c = origin_.to_enu(camera.eye.lon, camera.eye.lat, camera.eye.height);
    x.head<5>() << c[0] / 1000, c[1] / 1000, c[2] / 1000, camera.heading * kDegree,
        camera.pitch * kDegree;
    int k = 5;
    if (fit_focal_) x[k++] = std::log(PinholeCamera(camera).focal());
    if (bend_) {
      x[k++] = std::sqrt(1e5 / bend.radius);
      x[k] = std::sqrt(bend.start / 1000);
    }
    return x;
  }

  // False when x is out of the camera's range (pitch beyond +-90 degrees, fov beyond 170).
  bool unpack(const Eigen::VectorXd& x, CameraSpec& camera, ProgressiveBend& bend) const {
    camera.eye = origin_.to_geodetic(x[0] * 1000, x[1] * 1000, x[2] * 1000);
    camera.heading = x[3] / kDegree;
    camera.pitch = x[4] / kDegree;
    camera.width = options_.width;
    camera.height = options_.height;
    int k = 5;
    camera.fov = fit_focal_ ? fov_of_focal(std::exp(x[k++]), options_.width) : *options_.fov;
    bend = ProgressiveBend{};
    if (bend_) {
      bend.radius = 1e5 / (x[k] * x[k]);
      bend.start = 1000 * x[k + 1] * x[k + 1];
    }
    bend.base = ground - camera.eye.height;
    return std::abs(camera.pitch) <= 90 && camera.fov > 0 && camera.fov <= 170 &&
           !(bend.radius == 0);
  }

 private:
  const EnuFrame& origin_;
  const PaintingFitOptions& options_;
  bool fit_focal_, bend_;
};

struct Reprojection : Eigen::DenseFunctor<double> {
  Reprojection(const Unknowns& unknowns, const std::vector<GroundClick>& clicks,
               const std::vector<GeodeticPoint>& ground)
      : DenseFunctor(unknowns.size(), int(2 * clicks.size())),
        unknowns(&unknowns),
        clicks(&clicks),
        ground(&ground) {}

  int operator()(const InputType& x, ValueType& residuals) const {
    CameraSpec camera;
    ProgressiveBend bend;
    if (!unknowns->unpack(x, camera, bend)) {
      residuals.setConstant(kBehind);
      return 0;
    }
    const auto fitted = project_ground(camera, bend, *ground);
    for (size_t i = 0; i < fitted.size(); ++i) {
      const bool seen = std::isfinite(fitted[i][0]) && std::isfinite(fitted[i][1]);
      residuals[Eigen::Index(2 * i)] = seen ? fitted[i][0] - (*clicks)[i].x : kBehind;
      residuals[Eigen::Index(2 * i + 1)] = seen ? fitted[i][1] - (*clicks)[i].y : kBehind;
    }
    return 0;
  }

  const Unknowns* unknowns;
  const std::vector<GroundClick>* clicks;
  const std::vector<GeodeticPoint>* ground;
};

// Levenberg-Marquardt from x; returns the sum of squared residuals at the end.
double minimize(const Reprojection& reprojection, Eigen::VectorXd& x) {
  Eigen::NumericalDiff<Reprojection> diff(reprojection);
  Eigen::LevenbergMarquardt<Eigen::NumericalDiff<Reprojection>> lm(diff);
  lm.setMaxfev(400 * int(x.size()));
  lm.minimize(x);
  Eigen::VectorXd residuals(reprojection.values());
  reprojection(x, residuals);
  return residuals.squaredNorm();
}

// The camera solvePnP finds at `focal` (pixels) for points in `origin`'s frame, as the renderer's
// heading and pitch (its roll dropped); its reprojection error (sum of squares) beside it.
std::pair<CameraSpec, double> pnp_camera(const EnuFrame& origin,
                                         const std::vector<cv::Point3d>& world,
                                         const std::vector<cv::Point2d>& image, double focal,
                                         const PaintingFitOptions& options) {
  const cv::Matx33d k(focal, 0, options.width * 0.5 - 0.5, 0, focal, options.height * 0.5 - 0.5, 0,
                      0, 1);
  cv::Vec3d rvec, tvec;
  // SQPnP asserts on degenerate points (every click on one pixel): no camera at this focal length.
  try {
    if (!cv::solvePnP(world, image, k, cv::noArray(), rvec, tvec, false, cv::SOLVEPNP_SQPNP))
      return {{}, std::numeric_limits<double>::infinity()};
  } catch (const cv::Exception&) {
    return {{}, std::numeric_limits<double>::infinity()};
  }
  std::vector<cv::Point2d> projected;
  cv::projectPoints(world, rvec, tvec, k, cv::noArray(), projected);
  double error = 0;
  for (size_t i = 0; i < image.size(); ++i) {
    const cv::Point2d d = projected[i] - image[i];
    error += d.dot(d);
  }
  cv::Matx33d r;
  cv::Rodrigues(rvec, r);
  const cv::Vec3d eye = -(r.t() * tvec);  // in origin's frame
  CameraSpec camera;
  camera.eye = origin.to_geodetic(eye[0], eye[1], eye[2]);
  camera.width = options.width;
  camera.height = options.height;
  camera.fov = fov_of_focal(focal, options.width);
  // The camera's forward axis (row 2 of r) in the eye's own east-north-up frame.
  std::array<double, 9> axes;
  origin.to_enu(camera.eye.lon, camera.eye.lat, camera.eye.height, axes);
  double forward[3] = {0, 0, 0};
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) forward[j] += axes[size_t(3 * i + j)] * r(2, i);
  camera.heading = std::atan2(forward[0], forward[1]) / kDegree;
  camera.pitch = std::asin(std::clamp(forward[2], -1.0, 1.0)) / kDegree;
  return {camera, error};
}

// The plain camera with the least reprojection error over the scanned focal lengths (or the given
// one), as solvePnP finds it.
CameraSpec scan_cameras(const EnuFrame& origin, const std::vector<GroundClick>& clicks,
                        const PaintingFitOptions& options) {
  std::vector<cv::Point3d> world;
  std::vector<cv::Point2d> image;
  for (const GroundClick& c : clicks) {
    const auto p = origin.to_enu(c.ground.lon, c.ground.lat, c.ground.height);
    world.emplace_back(p[0], p[1], p[2]);
    image.emplace_back(c.x - 0.5, c.y - 0.5);  // OpenCV's pixel centres are at integers
  }
  std::vector<double> focals;
  const auto focal_of = [&](double fov) {
    return options.width * 0.5 / std::tan(fov * 0.5 * kDegree);
  };
  if (options.fov) {
    focals.push_back(focal_of(*options.fov));
  } else {
    for (double f = focal_of(120); f < focal_of(5); f *= 1.1) focals.push_back(f);
  }
  std::pair<CameraSpec, double> best{{}, std::numeric_limits<double>::infinity()};
  for (const double f : focals) {
    auto candidate = pnp_camera(origin, world, image, f, options);
    if (candidate.second < best.second) best = candidate;
  }
  if (!std::isfinite(best.second))
    throw Error(
        "painting fit: solvePnP found no camera: are the control points spread over the painting "
        "and over the ground?");
  return best.first;
}

}  // namespace

std::vector<PicturePoint> project_ground(const CameraSpec& camera, const ProgressiveBend& bend,
                                         const std::vector<GeodeticPoint>& ground) {
  const PinholeCamera pinhole(camera);
  std::vector<double> positions;
  positions.reserve(3 * ground.size());
  for (const GeodeticPoint& g : ground) {
    const auto p = pinhole.frame().to_enu(g.lon, g.lat, g.height);
    positions.insert(positions.end(), p.begin(), p.end());
  }
  bend_positions(positions, bend);
  std::vector<PicturePoint> pixels(ground.size());
  for (size_t i = 0; i < ground.size(); ++i) {
    const Vec3d view =
        pinhole.to_view({positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]});
    constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    pixels[i] = view[2] > 0 ? pinhole.to_pixel(view) : PicturePoint{kNaN, kNaN};
  }
  return pixels;
}

PaintingFit fit_painting(const std::vector<GroundClick>& clicks,
                         const PaintingFitOptions& options) {
  if (options.fov && !(*options.fov > 0 && *options.fov <= 170))
    throw Error("painting fit: fov " + std::to_string(*options.fov) +
                " is out of range (0, 170] degrees");
  // Two equations per click; the unknowns: the eye (3), heading, pitch, the focal length when not
  // given and the bend's radius and start; one click more than half of them, and at least 4.
  const size_t unknowns = 5 + !options.fov + 2 * options.bend;
  const size_t needed = std::max<size_t>(unknowns / 2 + 1, 4);
  if (clicks.size() < needed)
    throw Error("painting fit: " + std::to_string(clicks.size()) + " control points for " +
                std::to_string(unknowns) + " unknowns: give at least " + std::to_string(needed));
  // The frame at the points' centroid (on the ellipsoid).
  double lon = 0, lat = 0;
  for (const GroundClick& c : clicks) {
    lon += c.ground.lon;
    lat += c.ground.lat;
  }
  const EnuFrame origin({lon / double(clicks.size()), lat / double(clicks.size()), 0});
  std::vector<GeodeticPoint> ground;
  for (const GroundClick& c : clicks) ground.push_back(c.ground);

  PaintingFit fit;
  fit.camera = scan_cameras(origin, clicks, options);
  const Unknowns plain(origin, options, false);
  Eigen::VectorXd x = plain.pack(fit.camera, fit.bend);
  minimize(Reprojection(plain, clicks, ground), x);
  plain.unpack(x, fit.camera, fit.bend);

  if (options.bend) {
    // The points' median horizontal distance from the plain camera's eye scales the starts.
    const EnuFrame eye(fit.camera.eye);
    std::vector<double> distances;
    for (const GeodeticPoint& g : ground) {
      const auto p = eye.to_enu(g.lon, g.lat, g.height);
      distances.push_back(std::hypot(p[0], p[1]));
    }
    std::nth_element(distances.begin(), distances.begin() + std::ptrdiff_t(distances.size() / 2),
                     distances.end());
    const double median = distances[distances.size() / 2];
    Unknowns bent(origin, options, true);
    bent.ground = options.ground_height({fit.camera.eye.lon, fit.camera.eye.lat});
    const Reprojection reprojection(bent, clicks, ground);
    Eigen::VectorXd best;
    double error = std::numeric_limits<double>::infinity();
    for (const double radius : {0.5, 1.0, 2.0, 4.0})
      for (const double start : {0.1, 0.3, 0.6}) {
        Eigen::VectorXd y = bent.pack(fit.camera, {radius * median, start * median, 0});
        const double e = minimize(reprojection, y);
        if (e < error) {
          error = e;
          best = y;
        }
      }
    // The base follows the eye: solved again over the ground under the eye found, until it
    // settles (within 1 cm; the eye moves less at each round).
    for (int round = 0; round < 8; ++round) {
      bent.unpack(best, fit.camera, fit.bend);
      const double under = options.ground_height({fit.camera.eye.lon, fit.camera.eye.lat});
      if (std::abs(under - bent.ground) < 0.01) break;
      bent.ground = under;
      minimize(reprojection, best);
    }
    bent.unpack(best, fit.camera, fit.bend);
    // As render_job.h sets it.
    fit.bend.base =
        options.ground_height({fit.camera.eye.lon, fit.camera.eye.lat}) - fit.camera.eye.height;
  }
  fit.fitted = project_ground(fit.camera, fit.bend, ground);
  fit.ground = ground;
  double squares = 0;
  for (size_t i = 0; i < clicks.size(); ++i)
    squares +=
        std::pow(fit.fitted[i][0] - clicks[i].x, 2) + std::pow(fit.fitted[i][1] - clicks[i].y, 2);
  fit.rms_error = std::sqrt(squares / double(clicks.size()));
  if (!std::isfinite(fit.rms_error))
    throw Error("painting fit: no camera found sees every control point");
  if (options.warp_smoothing) {
    std::vector<PicturePoint> targets;
    for (const GroundClick& c : clicks) targets.push_back({c.x, c.y});
    const double scale = std::max(options.width, options.height);
    fit.warp = PictureWarp(fit.fitted, targets, scale, *options.warp_smoothing);
    fit.unwarp = PictureWarp(targets, fit.fitted, scale, *options.warp_smoothing);
  }
  return fit;
}

std::vector<PicturePoint> PaintingFit::to_painting(const std::vector<GeodeticPoint>& ground) const {
  auto pixels = project_ground(camera, bend, ground);
  for (auto& p : pixels) p = warp(p);
  return pixels;
}

}  // namespace maquette
