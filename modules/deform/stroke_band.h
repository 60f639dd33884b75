// A feature stroke's field of influence (paper 002 §3.2: the cross section's extent along the
// control curve): where the deformation may move the terrain.
#pragma once

#include <vector>

#include "mosaic_frame.h"

namespace maquette::deform {

// A stroke's field of influence in the frame's metres: the points whose signed distance from a
// segment of the curve (positive on the right of travel, measured perpendicular to the segment,
// whose projection falls on it) lies within the cross section's offsets [offset_min, offset_max],
// or, on the outer side of a bend where no segment's projection reaches (past one segment's end
// and before the next one's start), whose distance from the vertex, signed by the side, does;
// past the curve's ends, up to `end_margin_m` along it (the triangles that the end cross sections
// cross reach beyond them: held there, the ends' sections could not be met).
struct StrokeBand {
  std::vector<EastNorth2> curve;
  double offset_min = 0, offset_max = 0, end_margin_m = 0;

  bool contains(EastNorth2 p) const;
};

// Whether `p` lies in one of the bands.
bool in_any_band(const std::vector<StrokeBand>& bands, EastNorth2 p);

}  // namespace maquette::deform
