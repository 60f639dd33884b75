// Terrain Bender's progressive bending (Jenny, Jenny and Hurni 2011, "Interactive design of 3D
// maps with progressive projection"): beyond a start distance the ground curves up towards the
// horizon, so a panorama shows the far terrain from above and the near from the side, as a
// painted panorama does. The map, in the eye's east-north-up frame (metres; (e, n) horizontal,
// u up), about a base plane u = base (the ground under the eye): a point at horizontal distance
// d = hypot(e, n) <= start is left as it is; beyond, with theta = (d - start) / radius and
// rho = radius - (u - base) (the point's distance from the bend's axis, radius on the base
// plane), it moves to horizontal distance start + rho sin(theta), in the same direction from the
// eye, and to u = base + radius - rho cos(theta). So the base plane beyond the start is rolled
// onto the circle of `radius` tangent to it at d = start and centred `radius` above it, each
// point at its arc length d - start from the tangent point; a point h above the plane stays h
// above the circle along its normal. The map is continuous, with a continuous slope, at d = start;
// past theta = 90 degrees the ground leans back over the eye (the caller picks the radius).
#pragma once

#include <cmath>
#include <limits>
#include <span>
#include <vector>

namespace maquette {

struct ProgressiveBend {
  double radius = std::numeric_limits<double>::infinity();  // metres, > 0; infinite: no bend
  double start = 0;                                         // metres, >= 0
  double base = 0;  // the base plane's up coordinate in the eye's ENU frame, metres
  bool bends() const { return std::isfinite(radius); }
};

// Throws maquette::Error naming the option at fault: a radius not > 0 (--bend-radius) or a start
// not finite and >= 0 (--bend-start).
void check_bend(const ProgressiveBend& bend);

// Bends ENU `positions` (3 per vertex) in place as above; nothing changes (bit for bit) when the
// radius is infinite. Vertices are bent in parallel, each on its own: the same bits whatever the
// threads. Precondition: check_bend(bend) passes.
void bend_positions(std::span<double> positions, const ProgressiveBend& bend);

}  // namespace maquette
