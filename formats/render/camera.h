// A pinhole camera on the WGS84 ellipsoid for panoramas: its eye at a geodetic point, looking
// along a heading (degrees clockwise from north) and pitch (degrees above the eye's horizontal
// plane, negative looks down), with a horizontal field of view over a width x height picture of
// square pixels. Positions are in the east-north-up frame at the eye (core/enu_frame.h), so the
// earth's curvature is that of the ellipsoid, with no flat-earth approximation. Pixel (i, j) covers
// [i, i + 1) x [j, j + 1), its centre at (i + 0.5, j + 0.5), rows from the top.
#pragma once

#include <array>
#include <string>

#include "core/enu_frame.h"

namespace maquette {

using Vec3d = std::array<double, 3>;

struct CameraSpec {
  GeodeticPoint eye;   // height above the ellipsoid
  double heading = 0;  // degrees clockwise from north
  double pitch = 0;    // degrees, -90 (down) to 90 (up)
  double fov = 60;     // horizontal field of view, degrees, in (0, 170]
  int width = 1600, height = 900;
};

// The camera's place and aim for messages: "at lon -113.1000, lat 37.1200, 6500.0 m; heading 45,
// pitch -10, fov 50".
std::string view_text(const CameraSpec& spec);

// The heading and pitch (degrees) that aim the eye at `target`.
std::array<double, 2> aim(const GeodeticPoint& eye, const GeodeticPoint& target);

// Throws maquette::Error naming the field at fault: fov outside (0, 170], a heading not finite,
// pitch outside [-90, 90], width or height outside [1, 65536].
void check_camera_spec(const CameraSpec& spec);

class PinholeCamera {
 public:
  // Throws as check_camera_spec.
  explicit PinholeCamera(const CameraSpec& spec);

  const CameraSpec& spec() const { return spec_; }
  const EnuFrame& frame() const { return frame_; }
  // Pixels per unit of tan(angle): the focal length in pixels.
  double focal() const { return focal_; }

  // A point of the eye's ENU frame in the camera's frame: x right, y down, z forward (metres).
  // Inline: the mesh's every vertex goes through it.
  Vec3d to_view(const Vec3d& p) const {
    auto dot = [&p](const Vec3d& a) { return a[0] * p[0] + a[1] * p[1] + a[2] * p[2]; };
    return {dot(right_), dot(down_), dot(forward_)};
  }
  // The picture coordinates of a camera-frame point with z > 0 (pixel centres at i + 0.5).
  std::array<double, 2> to_pixel(const Vec3d& view) const {
    return {spec_.width * 0.5 + focal_ * view[0] / view[2],
            spec_.height * 0.5 + focal_ * view[1] / view[2]};
  }
  // The ray through picture coordinates (x, y) in the eye's ENU frame, scaled to a forward
  // (camera z) component of 1: a point at camera depth z is z times it. Inline: every terrain
  // pixel's distance goes through it.
  Vec3d ray(double x, double y) const { return ray(column_ray(x), row_ray(y)); }
  // That ray's two parts, column_ray(x) + row_ray(y) component by component (the same bits): the
  // pixels of a row share the one, those of a column the other.
  Vec3d column_ray(double x) const {
    const double u = (x - spec_.width * 0.5) / focal_;
    return {forward_[0] + u * right_[0], forward_[1] + u * right_[1], forward_[2] + u * right_[2]};
  }
  Vec3d row_ray(double y) const {
    const double v = (y - spec_.height * 0.5) / focal_;
    return {v * down_[0], v * down_[1], v * down_[2]};
  }
  static Vec3d ray(const Vec3d& column, const Vec3d& row) {
    return {column[0] + row[0], column[1] + row[1], column[2] + row[2]};
  }

 private:
  CameraSpec spec_;
  EnuFrame frame_;
  double focal_;
  Vec3d right_, down_, forward_;  // the camera's axes in the ENU frame
};

}  // namespace maquette
