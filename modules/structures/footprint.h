// A building's footprint as a polygon of a local plane (metres east and north), checked for the
// solid it must give (val3dity's ring and shell rules): rings simple, none crossing or touching
// another, holes inside the outer ring and outside each other, no ring of zero area.
#pragma once

#include <array>
#include <stdexcept>
#include <vector>

namespace maquette::structures {

using PlanePoint2 = std::array<double, 2>;
using PlaneRing = std::vector<PlanePoint2>;  // open: the last point is not the first again

// A ring below this area (m^2) cannot give a solid: a sliver or a line.
inline constexpr double kMinRingAreaM2 = 0.01;

// Why a footprint cannot give a valid solid, for the user (the caller adds the feature id).
class InvalidFootprint : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Outer ring counter-clockwise, holes clockwise (seen from above), each ring open, without
// repeated consecutive points, starting at its input's first point.
struct Footprint {
  std::vector<PlaneRing> rings;  // outer first
  double area = 0;               // m^2, holes taken off
};

double signed_area(const PlaneRing& ring);  // counter-clockwise positive, open ring

// The footprint of rings (outer first, then holes; closed or open, either orientation).
// Throws InvalidFootprint naming the ring (0: outer, k: hole k) and what is wrong: fewer than 3
// distinct points, area below kMinRingAreaM2, two edges crossing or touching (with the point),
// a hole outside the outer ring or inside another hole. O(n^2) in the edges: footprints have
// tens of points.
Footprint make_footprint(std::vector<PlaneRing> rings);

// The parts of a MultiPolygon (each from make_footprint) give disjoint solids: no edges of two
// parts meet, and no part lies on another (a part in another's hole is fine). Throws
// InvalidFootprint naming the parts (from 0).
void check_disjoint(const std::vector<Footprint>& parts);

}  // namespace maquette::structures
