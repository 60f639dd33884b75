// Rotation-minimizing frames along a sampled curve by double reflection (Wang, Jüttler, Zheng,
// Liu, "Computation of rotation minimizing frames", ACM TOG 27(1), 2008): the paper's cross
// sections (paper 002 §3.2.2) are oriented with them, so they do not twist around the curve.
#pragma once

#include <array>
#include <vector>

namespace maquette::deform {

using Vec3d = std::array<double, 3>;

struct Frame {
  Vec3d tangent;    // unit
  Vec3d reference;  // unit, orthogonal to the tangent: the frame's rotation-minimizing normal
};

// The frames at `points` (at least two, consecutive points distinct), with unit `tangents` there
// (same count), starting from `reference0` (orthogonal to tangents[0], unit). Each frame is the
// previous one reflected in the bisector plane of the step, then in the plane that maps the
// reflected tangent onto the next one (the algorithm's fourth-order accurate step, exact for a
// planar curve whose reference lies in its plane).
std::vector<Frame> rotation_minimizing_frames(const std::vector<Vec3d>& points,
                                              const std::vector<Vec3d>& tangents,
                                              const Vec3d& reference0);

}  // namespace maquette::deform
