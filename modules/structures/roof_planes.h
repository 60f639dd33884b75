// A pitched roof as planes over a footprint: the roof is their lowest at every point (a height
// field min over planes), so any footprint, concave or with courtyards, takes it (roof_surface.h).
#pragma once

#include "building_height.h"
#include "footprint.h"

namespace maquette::structures {

// A plane over the footprint's plane: z = a x + b y + c (metres).
struct RoofPlane {
  double a = 0, b = 0, c = 0;
  double at(const PlanePoint2& p) const { return a * p[0] + b * p[1] + c; }
};

// The roof's frame: unit vectors `along` the ridge and `across` it (across = along turned 90
// degrees counter-clockwise), and the outer ring's bounding rectangle in them: u = p . along in
// [u0, u1], v = p . across in [v0, v1].
struct RoofFrame {
  PlanePoint2 along{1, 0}, across{0, 1};
  double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
};

// The ridge along the longer side of the outer ring's least-area bounding rectangle (a
// rectangle's longer principal axis; for any footprint the rectangle whose sides follow its walls
// best, where the principal axes of a square or an L are arbitrary), along the shorter with
// tags.across; `along` pointing east, or north when it runs north-south. With tags.direction_deg,
// `across` is that direction (where the main face looks) whatever the footprint. Precondition:
// `footprint` from make_footprint.
RoofFrame roof_frame(const Footprint& footprint, const BuildingTags& tags);

// The horizontal distance from an eave to the roof's top: half the rectangle's width across the
// ridge (gabled), half its shorter side (hipped, pyramidal), its whole width (skillion); 0 (flat).
double roof_run(const RoofFrame& frame, RoofShape shape);

// The planes of `shape` over the frame's rectangle, their eaves on its sides at z = heights.wall,
// the roof's top at heights.top():
// - flat: one horizontal plane at the top (the wall then is the top);
// - gabled: two planes meeting in the ridge over the rectangle's middle line along `along`;
// - hipped: four planes of one slope from the four sides (the rectangle's straight skeleton: a
//   ridge over its middle of length long side - short side, hips at 45 degrees in plan);
// - pyramidal: four planes from the four sides meeting over the rectangle's centre;
// - skillion: one plane, rising from the side `across` points to (the eave) to the opposite side.
std::vector<RoofPlane> roof_planes(const RoofFrame& frame, RoofShape shape,
                                   const PartHeights& heights);

}  // namespace maquette::structures
