// Which base triangles to subdivide adaptively: those near a feature's curve.
#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

#include "loop_mesh.h"

namespace maquette::deform {

// Per triangle of `mesh`: whether its projection on the (x, y) plane comes within `distance`
// metres of the polyline (exact 2D distance between the triangle and the segments).
// Preconditions (std::invalid_argument otherwise): at least two points, distance >= 0 and finite.
std::vector<bool> triangles_near_polyline(const TriangleMesh& mesh,
                                          std::span<const Eigen::Vector2d> polyline,
                                          double distance);

}  // namespace maquette::deform
