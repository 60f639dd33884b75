// structures.prism's solver (README.md "structures.prism"; paper 002 §7.2, after Chen et al.'s
// 3-Sweep): a right prism's geometry, up to scale, and the camera, from clicks in one photo.
//
// The photo: a pinhole camera (Eq. 7) with focal length `focal_px` (pixels), principal point
// (u, v), no skew, no distortion; camera frame x right, y down, z forward (OpenCV's).
// The clicks (pixels, x right, y down from the image's top-left corner):
// - `profile`: the vertices of one visible planar side of the prism (the profile), in order
//   around it, a simple polygon in 3D; the vertex `corner` has a right angle;
// - `extrusion`: where the edge from the corner orthogonal to the profile ends (Q of the corner);
// - optionally more ends of extrusion edges (Q_i of other profile vertices i).
// The minimal clicks (profile and one extrusion end) determine the prism exactly; every further
// click is used by the least squares refinement.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

namespace maquette::structures {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;

struct PrismClicks {
  std::vector<Vec2> profile;  // >= 3 vertices
  int corner = 0;             // index in profile of the right-angled vertex (P1 of Eq. 6)
  Vec2 extrusion;             // Q of the corner
  // Further extrusion ends: (profile index, Q_i), each index other than the corner at most once.
  std::vector<std::pair<int, Vec2>> more_extrusions;
};

struct PinholeCamera {
  double focal_px = 0;
  Vec2 principal;                          // (u, v), pixels
  Vec3 ray(const Vec2& pixel) const;       // (x - u, y - v, f) / f: the point at depth 1
  Vec2 project(const Vec3& camera) const;  // precondition: camera.z() > 0
};

// The prism in the camera's frame, up to one scale (the corner's depth is 1).
struct PrismSolution {
  std::vector<Vec3> profile;  // P_i, in the clicks' order
  int corner = 0;             // the clicks' corner
  Vec3 extrusion;             // Q_i - P_i for every i: orthogonal to the profile's plane
  // Σ squared reprojection errors of every click (pixels²) after refinement.
  double residual_px2 = 0;
  double focal_px = 0;   // the camera's, estimated when solve_prism was asked to
  int roots = 0;         // candidate roots of Eq. 9 in front of the camera
  bool refined = false;  // whether least squares had more clicks than unknowns
};

// The candidate solutions of Eq. 9 for the corner's three edges (P0 = profile vertex before the
// corner, P2 = the one after, Q1 = the extrusion end), corner depth 1: the quadratic's real roots
// with all four points in front of the camera (z > 0), each with the remaining profile vertices
// put on the plane of P0, P1, P2 (their rays cut it). Empty when no root qualifies.
std::vector<PrismSolution> prism_roots(const PrismClicks& clicks, const PinholeCamera& camera);

// The root the check keeps: the profile is a visible side of the prism, so the prism's body lies
// behind it, seen from the camera: the extrusion points away from the camera (P1 . (Q1 - P1) > 0,
// the camera at the origin). Of Eq. 9's two roots (a Necker pair: the corner seen convex or
// concave) exactly one passes; std::nullopt when none or both do (the clicks are ambiguous).
std::optional<PrismSolution> checked_root(const std::vector<PrismSolution>& roots);

// The solution: the checked root refined by Gauss-Newton over every click (reprojection errors
// in pixels) when the clicks over-determine it: rotation of the prism's axes, corner position on
// its ray, the profile's in-plane coordinates (the corner's edges stay on their axes: its right
// angle holds) and the extrusion's length. Throws maquette::Error prefixed with `where` when
// the clicks are degenerate (fewer than 3 profile vertices, a bad index, collinear corner edges)
// or no root passes the check, naming the reason. With `estimate_focal`, camera.focal_px is only
// the start: the focal length is one more unknown of the refinement (it needs at least one click
// beyond the minimal ones; without, the start is kept).
PrismSolution solve_prism(const PrismClicks& clicks, const PinholeCamera& camera,
                          const std::string& where, bool estimate_focal = false);

}  // namespace maquette::structures
