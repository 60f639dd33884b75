#include "roof_planes.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace maquette::structures {
namespace {

// A unit vector pointing east, or north when the vector runs north-south: one of v and -v.
PlanePoint2 eastwards(const PlanePoint2& v) {
  return v[0] > 0 || (v[0] == 0 && v[1] > 0) ? v : PlanePoint2{-v[0], -v[1]};
}

// The extents of the ring along the unit vector d and across it.
std::pair<double, double> extents(const PlaneRing& ring, const PlanePoint2& d) {
  double u0 = INFINITY, u1 = -INFINITY, v0 = INFINITY, v1 = -INFINITY;
  for (const PlanePoint2& p : ring) {
    const double u = p[0] * d[0] + p[1] * d[1], v = p[1] * d[0] - p[0] * d[1];
    u0 = std::min(u0, u), u1 = std::max(u1, u), v0 = std::min(v0, v), v1 = std::max(v1, v);
  }
  return {u1 - u0, v1 - v0};
}

// The longer side's direction of the ring's least-area bounding rectangle: one has a side along
// an edge of the convex hull (Freeman and Shapira), so trying the ring's edges finds it; the first
// edge on a tie. O(n^2) in the points: footprints have tens.
PlanePoint2 long_axis(const PlaneRing& ring) {
  PlanePoint2 best{1, 0};
  double least = INFINITY;
  for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const double dx = ring[i][0] - ring[j][0], dy = ring[i][1] - ring[j][1];
    const double length = std::hypot(dx, dy);
    const PlanePoint2 d{dx / length, dy / length};
    const auto [along, across] = extents(ring, d);
    if (along * across < least) {
      least = along * across;
      best = along >= across ? d : PlanePoint2{-d[1], d[0]};
    }
  }
  return eastwards(best);
}

// A plane rising from the line p . g = t0 at z0, along the horizontal unit vector g, by `slope`.
RoofPlane rising(const PlanePoint2& g, double t0, double z0, double slope) {
  return {slope * g[0], slope * g[1], z0 - slope * t0};
}

}  // namespace

RoofFrame roof_frame(const Footprint& footprint, const BuildingTags& tags) {
  RoofFrame f;
  if (tags.direction_deg) {
    const double d = *tags.direction_deg * std::numbers::pi / 180;
    f.across = {std::sin(d), std::cos(d)};
    f.along = {f.across[1], -f.across[0]};
  } else {
    f.along = long_axis(footprint.rings[0]);
    if (tags.across) f.along = eastwards({-f.along[1], f.along[0]});
    f.across = {-f.along[1], f.along[0]};
  }
  f.u0 = f.v0 = INFINITY;
  f.u1 = f.v1 = -INFINITY;
  for (const PlanePoint2& p : footprint.rings[0]) {
    const double u = p[0] * f.along[0] + p[1] * f.along[1];
    const double v = p[0] * f.across[0] + p[1] * f.across[1];
    f.u0 = std::min(f.u0, u), f.u1 = std::max(f.u1, u);
    f.v0 = std::min(f.v0, v), f.v1 = std::max(f.v1, v);
  }
  return f;
}

double roof_run(const RoofFrame& f, RoofShape shape) {
  const double length = f.u1 - f.u0, width = f.v1 - f.v0;
  switch (shape) {
    case RoofShape::Gabled:
      return width / 2;
    case RoofShape::Hipped:
    case RoofShape::Pyramidal:
      return std::min(length, width) / 2;
    case RoofShape::Skillion:
      return width;
    case RoofShape::Flat:
      break;
  }
  return 0;
}

std::vector<RoofPlane> roof_planes(const RoofFrame& f, RoofShape shape, const PartHeights& h) {
  const PlanePoint2 back_along{-f.along[0], -f.along[1]}, back_across{-f.across[0], -f.across[1]};
  const double length = f.u1 - f.u0, width = f.v1 - f.v0;
  // Planes rising inwards from the long sides (slope s) and, when t > 0, from the ends (slope t).
  const auto inwards = [&](double s, double t) {
    std::vector<RoofPlane> planes = {rising(f.across, f.v0, h.wall, s),
                                     rising(back_across, -f.v1, h.wall, s)};
    if (t > 0)
      planes.insert(planes.end(),
                    {rising(f.along, f.u0, h.wall, t), rising(back_along, -f.u1, h.wall, t)});
    return planes;
  };
  switch (shape) {
    case RoofShape::Gabled:
      return inwards(h.roof / (width / 2), 0);
    case RoofShape::Hipped: {
      const double slope = h.roof / (std::min(length, width) / 2);
      return inwards(slope, slope);
    }
    case RoofShape::Pyramidal:
      return inwards(h.roof / (width / 2), h.roof / (length / 2));
    case RoofShape::Skillion:
      return {rising(back_across, -f.v1, h.wall, h.roof / width)};
    case RoofShape::Flat:
      break;
  }
  return {{0, 0, h.top()}};
}

}  // namespace maquette::structures
