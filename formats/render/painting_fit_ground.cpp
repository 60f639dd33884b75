#include "render/painting_fit_ground.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "core/error.h"

namespace maquette {
namespace {

// The move (east, north metres in `eye`'s frame) of `ground`, its height kept, that the camera and
// bend draw on `pixel`: Newton's method on the two pixel coordinates, the Jacobian by forward
// differences of 10 cm. Nothing when the ray through `pixel` does not reach the point's height
// (or the move leaves it behind the eye).
std::optional<PicturePoint> move_onto(const EnuFrame& eye, const CameraSpec& camera,
                                      const ProgressiveBend& bend, const GeodeticPoint& ground,
                                      const PicturePoint& pixel) {
  const auto at = eye.to_enu(ground.lon, ground.lat, 0);
  const auto drawn = [&](double east, double north) {
    GeodeticPoint p = eye.to_geodetic(at[0] + east, at[1] + north, at[2]);
    p.height = ground.height;
    return project_ground(camera, bend, {p})[0];
  };
  constexpr double kStep = 0.1;      // metres
  constexpr double kSettled = 1e-4;  // pixels
  PicturePoint move{0, 0};
  for (int round = 0; round < 30; ++round) {
    const PicturePoint f = drawn(move[0], move[1]);
    const double rx = f[0] - pixel[0], ry = f[1] - pixel[1];
    if (!std::isfinite(rx) || !std::isfinite(ry)) return std::nullopt;
    if (std::hypot(rx, ry) < kSettled) return move;
    const PicturePoint fe = drawn(move[0] + kStep, move[1]), fn = drawn(move[0], move[1] + kStep);
    const double a = (fe[0] - f[0]) / kStep, b = (fn[0] - f[0]) / kStep, c = (fe[1] - f[1]) / kStep,
                 d = (fn[1] - f[1]) / kStep;
    const double det = a * d - b * c;
    if (!std::isfinite(det) || det == 0) return std::nullopt;
    move[0] -= (d * rx - b * ry) / det;
    move[1] -= (a * ry - c * rx) / det;
  }
  return std::nullopt;
}

// 1 at s <= 1, 0 at s >= 2, a smoothstep between (continuous slope).
double fade(double distance, double reach) {
  if (distance <= reach) return 1;
  if (distance >= 2 * reach) return 0;
  const double t = (distance - reach) / reach;
  return 1 - t * t * (3 - 2 * t);
}

}  // namespace

GroundWarp::GroundWarp(const PaintingFit& fit, double dem_sample_m) : eye_(fit.camera.eye) {
  std::vector<PicturePoint> from;
  double west = std::numeric_limits<double>::infinity(), east = -west, south = west, north = -west;
  for (size_t i = 0; i < fit.ground.size(); ++i) {
    const PicturePoint target = fit.warp(fit.fitted[i]);
    const auto move = move_onto(eye_, fit.camera, fit.bend, fit.ground[i], target);
    if (!move)
      throw Error("warped DEM: no horizontal move of points[" + std::to_string(i) +
                  "]'s ground point puts it on its pixel (" + std::to_string(target[0]) + ", " +
                  std::to_string(target[1]) + ") under the fitted camera");
    const auto g = eye_.to_enu(fit.ground[i].lon, fit.ground[i].lat, 0);
    from.push_back(PicturePoint{g[0], g[1]});
    centres_.push_back({g[0] + (*move)[0], g[1] + (*move)[1]});
    moves_.push_back(*move);
    west = std::min(west, centres_.back()[0]);
    east = std::max(east, centres_.back()[0]);
    south = std::min(south, centres_.back()[1]);
    north = std::max(north, centres_.back()[1]);
  }
  spline_ = PictureWarp(centres_, from, std::max(east - west, north - south), 0);
  for (size_t i = 0; i < centres_.size(); ++i) {
    double nearest = std::numeric_limits<double>::infinity();
    for (size_t j = 0; j < centres_.size(); ++j)
      if (j != i)
        nearest = std::min(
            nearest, std::hypot(centres_[i][0] - centres_[j][0], centres_[i][1] - centres_[j][1]));
    reach_.push_back(std::max(nearest, 2 * dem_sample_m));
  }
}

double GroundWarp::weight(double east, double north) const {
  double w = 0;
  for (size_t i = 0; i < centres_.size() && w < 1; ++i)
    w = std::max(w, fade(std::hypot(east - centres_[i][0], north - centres_[i][1]), reach_[i]));
  return w;
}

LonLat GroundWarp::source(LonLat p) const {
  const auto x = eye_.to_enu(p.lon, p.lat, 0);
  const double w = weight(x[0], x[1]);
  if (w == 0) return p;
  const PicturePoint s = spline_({x[0], x[1]});
  const GeodeticPoint g =
      eye_.to_geodetic(x[0] + w * (s[0] - x[0]), x[1] + w * (s[1] - x[1]), x[2]);
  return {g.lon, g.lat};
}

bool GroundWarp::still_near(LonLat p, double radius) const {
  const auto x = eye_.to_enu(p.lon, p.lat, 0);
  for (size_t i = 0; i < centres_.size(); ++i)
    if (std::hypot(x[0] - centres_[i][0], x[1] - centres_[i][1]) - radius < 2 * reach_[i])
      return false;
  return true;
}

}  // namespace maquette
