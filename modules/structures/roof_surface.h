// A roof's surface over a footprint: the lowest of its planes at every point (roof_planes.h),
// triangulated face by face, the footprint split along the lines where the planes meet (creases).
#pragma once

#include <cstdint>
#include <vector>

#include "footprint.h"
#include "roof_planes.h"

namespace maquette::structures {

// A point within this distance of a crease (m) is taken as on it: a crease through a corner of
// the footprint (a hip through a rectangle's corner) adds no point a rounding away from it.
// Such a point's height (the lowest plane) is then off the other plane by at most this times the
// planes' slopes, far within the 1 cm of a face's planarity. Small, so that creases meeting at
// small angles near a point are still told apart (1 mm was not, on Soho's footprints); a crease
// passing a little further from a corner leaves a thin triangle, caught as a sliver.
inline constexpr double kCreaseSnapM = 1e-4;

struct RoofSurface {
  // The footprint's points, ring after ring, then the points added where creases cross the
  // footprint's triangles (and, rarely, one inside a piece triangulated around it).
  std::vector<PlanePoint2> points;
  std::vector<double> heights;  // per point: the roof there (the lowest plane)
  // Per plane that shows: its triangles (indices into points, counter-clockwise from above).
  std::vector<std::vector<uint32_t>> faces;
  // Per ring of the footprint: its points in order from its first, with those where creases
  // cross it (a gable wall's apex, a hip's foot).
  std::vector<std::vector<uint32_t>> outline;

  // The volume between the surface and z = 0 (m^3): each triangle's plan area x its mean height,
  // exact for a surface linear on each triangle.
  double volume() const;
};

// The surface of `planes` (at least one) over `footprint` (from make_footprint): its triangles
// (roof_triangulation.h), with the points where three planes meet as the lowest (a hip's end, a
// pyramid's apex) inserted, cut by each plane's region where it is the lowest (a convex polygon:
// Sutherland-Hodgman), points on a crease computed once per footprint triangle edge and crease
// (the same bits on both sides of the edge), points of several creases met within 10 nanometres
// made one. Every point's height is the lowest plane there, so faces meet exactly along creases.
// Throws InvalidFootprint when the pieces do not close around the footprint's rings (a crease
// grazing the footprint within kCreaseSnapM): the caller may build the roof flat instead.
RoofSurface roof_surface(const Footprint& footprint, const std::vector<RoofPlane>& planes);

}  // namespace maquette::structures
