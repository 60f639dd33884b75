#include "render/camera.h"

#include <spdlog/fmt/fmt.h>

#include <cmath>
#include <numbers>
#include <string>

#include "core/error.h"

namespace maquette {
namespace {

constexpr double kDegree = std::numbers::pi / 180;

}  // namespace

std::string view_text(const CameraSpec& spec) {
  return fmt::format(
      "at lon {:.4f}, lat {:.4f}, {:.1f} m; heading {:.4g}, pitch {:.4g}, fov {:.4g}", spec.eye.lon,
      spec.eye.lat, spec.eye.height, spec.heading, spec.pitch, spec.fov);
}

std::array<double, 2> aim(const GeodeticPoint& eye, const GeodeticPoint& target) {
  const auto d = EnuFrame(eye).to_enu(target.lon, target.lat, target.height);
  if (d[0] == 0 && d[1] == 0 && d[2] == 0) throw Error("--look-at is the camera's own position");
  return {std::atan2(d[0], d[1]) / kDegree, std::atan2(d[2], std::hypot(d[0], d[1])) / kDegree};
}

void check_camera_spec(const CameraSpec& spec) {
  if (!(spec.fov > 0 && spec.fov <= 170))
    throw Error("camera fov " + std::to_string(spec.fov) +
                " is out of range: the horizontal field of view must be in (0, 170] degrees");
  if (!std::isfinite(spec.heading))
    throw Error("camera heading " + std::to_string(spec.heading) + " is not finite");
  if (!(spec.pitch >= -90 && spec.pitch <= 90))
    throw Error("camera pitch " + std::to_string(spec.pitch) + " is out of range [-90, 90]");
  if (spec.width < 1 || spec.height < 1 || spec.width > 65536 || spec.height > 65536)
    throw Error("picture size " + std::to_string(spec.width) + " x " + std::to_string(spec.height) +
                " is out of range [1, 65536]");
}

PinholeCamera::PinholeCamera(const CameraSpec& spec) : spec_(spec), frame_(spec.eye) {
  check_camera_spec(spec);
  focal_ = spec.width * 0.5 / std::tan(spec.fov * 0.5 * kDegree);
  const double h = spec.heading * kDegree, p = spec.pitch * kDegree;
  forward_ = {std::sin(h) * std::cos(p), std::cos(h) * std::cos(p), std::sin(p)};
  right_ = {std::cos(h), -std::sin(h), 0};
  // down = forward x right (right-handed: right x down = forward).
  down_ = {forward_[1] * right_[2] - forward_[2] * right_[1],
           forward_[2] * right_[0] - forward_[0] * right_[2],
           forward_[0] * right_[1] - forward_[1] * right_[0]};
}

}  // namespace maquette
