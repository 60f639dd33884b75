// A bridge stroke (../shared/DESIGN.md, "Strokes"): a feature of tool "bridge" whose geometry is a
// MultiLineString of exactly two LineStrings, the deck's edges (Fig. 16 of paper 002: the two
// edges of the bridge not attached to the terrain, each from one bank to the other), and an
// optional `thickness_m` (a positive number of metres up to kMaxDeckThicknessM, the deck's
// thickness below its top).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/geometry.h"
#include "runtime/vector_feature.h"

namespace maquette::structures {

inline constexpr double kMaxDeckThicknessM = 100;  // the step parameter's maximum too

struct BridgeStroke {
  int64_t id = 0;
  std::vector<GeoPoint> first_edge, second_edge;  // each from the same bank to the other
  double thickness_m = 0;
};

bool is_bridge_stroke(const VectorFeature& f);  // its attribute tool is "bridge"

// The bridge of feature `f` (tool "bridge"), `default_thickness_m` when it has no thickness_m.
// The second edge is turned round when drawn from the other bank (its first point nearer the
// first edge's last point than its first, in degrees scaled by the cosine of the latitude).
// Throws maquette::Error naming the feature and the field at fault: a geometry other than a
// MultiLineString of two LineStrings, an edge of fewer than 2 distinct points, a thickness_m that
// is not a positive number up to kMaxDeckThicknessM.
BridgeStroke bridge_stroke(const VectorFeature& f, double default_thickness_m);

}  // namespace maquette::structures
