// Synthetic "paintings" for the painting fit's tests: ground points of an analytic terrain seen by
// the tests' own pinhole (test_camera.h) in PROJ's east-north-up frame at the eye (proj_enu.h),
// optionally bent by the tests' own progressive bend, clicked with noise.
#pragma once

#include <array>
#include <optional>
#include <random>
#include <vector>

#include "proj_enu.h"
#include "render/painting_fit.h"
#include "test_camera.h"

namespace maquette::test {

// Hills over a plain 400 m above the ellipsoid, heights above the ellipsoid (metres).
double synthetic_terrain(double lon, double lat);

struct SyntheticPainting {
  double eye_lon = 0, eye_lat = 0, eye_height = 0;  // metres above the ellipsoid
  TestCamera camera;                                // heading, pitch, fov, width, height
  double bend_radius = 0, bend_start = 0;           // no bend when the radius is 0
  // The painter's distortion: the picture around its centre magnified, each point moved away from
  // the centre by up to `bulge` pixels, bulge * exp(-r^2 / (2 s^2)) * r / s at distance r, s a
  // sixth of the width.
  double bulge = 0;
  // Ground points are drawn in this box of degrees.
  double west = 0, east = 0, south = 0, north = 0;

  // Where the painting shows a ground point (picture coordinates, render/camera.h), `enu` the
  // frame at the eye; nullopt when it is behind the eye or outside the painting.
  std::optional<std::array<double, 2>> pixel(const ProjEnu& enu, const GeodeticPoint& ground) const;
  // `count` ground points shown in the painting, each clicked off by an isotropic Gaussian error
  // of root-mean-square length `noise` pixels (`noise` 0: exactly).
  std::vector<GroundClick> clicks(size_t count, double noise, std::mt19937& random) const;
};

// A view north over the hills, 3 km above the ellipsoid.
SyntheticPainting plain_painting();
// A bent view: the ground beyond 6 km curves up on a circle of 35 km, so the far hills, up to 60 km
// away, are seen from above.
SyntheticPainting bent_painting();

// The median and 90th percentile of the distances between `fitted` and the points' true pixels.
std::array<double, 2> error_percentiles(const SyntheticPainting& painting,
                                        const std::vector<GroundClick>& truth,
                                        const std::vector<std::array<double, 2>>& fitted);

}  // namespace maquette::test
