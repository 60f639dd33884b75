// Synthetic photos of right prisms for structures.prism's oracle tests: known prisms seen by known
// cameras, their vertices projected by OpenCV (cv::projectPoints, independent of the solver's
// camera model), the clicks perturbed by Gaussian noise.
#pragma once

#include <cstdint>
#include <vector>

#include "../prism_solver.h"

namespace maquette::structures {

// A photo of a prism whose profile lies in the world plane y = 0 (x along its base, z up), the
// corner (vertex 0) at the origin with its edges along +x (the last vertex) and +z (vertex 1),
// the body extruded along +y by `length`.
struct SyntheticPhoto {
  std::vector<Vec3> profile;      // world metres
  double length = 0;              // the extrusion
  std::vector<int> right_angles;  // profile vertices with a right angle, the corner excluded
  Eigen::Matrix3d rotation;       // world -> camera
  Vec3 translation;               // world -> camera
  PinholeCamera camera;
  int width = 0, height = 0;
  // Whether the camera sees each facet (the profile, the far cap, the side of each profile edge
  // i -> i + 1): whether it faces the camera's centre (the prisms are convex).
  std::vector<bool> facet_visible;
  PrismClicks exact;   // projected without noise
  PrismClicks clicks;  // with the noise
  Vec3 camera_centre() const { return -rotation.transpose() * translation; }
  // A world point in the camera frame scaled as the solver's (the corner at depth 1).
  Vec3 to_solver_frame(const Vec3& world) const;
};

// Photo `index` of the deterministic series from `seed`: a rectangle, a right trapezoid or a gabled
// profile (5-30 m wide, 3-20 m high, extruded 5-40 m); a camera with a focal length of 0.6-2 image
// widths (1200 x 900 pixels) seeing the profile and the wall of its corner's vertical edge from
// 1.1-2.5 times the distance that fits the prism in the frame, at -5..45 degrees of elevation,
// every vertex in the photo, no facet within 3 degrees of edge-on (neither clearly visible nor
// hidden), the profile and the wall of the corner's vertical edge seen at 10 degrees or more
// (sides a user would click), the corner's three edges at least 50 pixels long; `noise_px` the
// standard deviation of each click's coordinates; `more_extrusions` the ends of as many extrusion
// edges of other profile vertices (first, then last, then second...), also clicked.
SyntheticPhoto synthetic_photo(uint64_t seed, int index, double noise_px, int more_extrusions = 0);

}  // namespace maquette::structures
