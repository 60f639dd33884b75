// The tests' own pinhole camera, built apart from render/camera.h: the rotation from the eye's
// east-north-up frame to the camera's (x right, y down, z forward) as a product of elementary
// rotations (heading about up, then the level camera's axes, then pitch about its x axis).
#pragma once

#include <array>

namespace maquette::test {

using Matrix3 = std::array<std::array<double, 3>, 3>;

struct TestCamera {
  double heading = 0, pitch = 0, fov = 60;  // degrees
  int width = 0, height = 0;

  Matrix3 rotation() const;  // ENU -> camera
  double focal() const;      // pixels
  // OpenCV's convention: pixel (i, j)'s centre at (i, j).
  double cx() const { return width * 0.5 - 0.5; }
  double cy() const { return height * 0.5 - 0.5; }
  // The ENU direction through the centre of pixel (col, row), not normalized.
  std::array<double, 3> ray(int col, int row) const;
  // The pixel coordinates (OpenCV convention) of an ENU point in front of the eye.
  std::array<double, 2> project(const std::array<double, 3>& enu) const;
};

// The tests' own progressive bend of an ENU point (metres, the eye at the origin), as a rotation:
// beyond `start`, the vertical section through the eye turned by (d - start) / radius about the
// axis `radius` above the ground plane at up = `base`.
std::array<double, 3> bent(const std::array<double, 3>& p, double radius, double start,
                           double base);

}  // namespace maquette::test
