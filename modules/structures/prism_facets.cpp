#include "prism_facets.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace maquette::structures {
namespace {

Vec3 mean(const std::vector<Vec3>& points) {
  Vec3 sum = Vec3::Zero();
  for (const Vec3& p : points) sum += p;
  return sum / double(points.size());
}

// Whether `p`, on the facet's plane, lies inside it (crossing number in the facet's 2D frame).
bool inside(const PrismFacet& facet, const Vec3& p) {
  const Vec3 u = (facet.corners[1] - facet.corners[0]).normalized();
  const Vec3 v = facet.normal.cross(u);
  const auto flat = [&](const Vec3& q) { return Vec2((q - p).dot(u), (q - p).dot(v)); };
  bool in = false;
  for (size_t i = 0, j = facet.corners.size() - 1; i < facet.corners.size(); j = i++) {
    const Vec2 a = flat(facet.corners[i]), b = flat(facet.corners[j]);
    if ((a.y() > 0) != (b.y() > 0) && a.x() + (b.x() - a.x()) * (0 - a.y()) / (b.y() - a.y()) > 0)
      in = !in;
  }
  return in;
}

// The facet's extents along its first edge and along the axis after it, the smaller first (the
// caps' first edges differ).
Vec2 extents(const PrismFacet& facet) {
  const Vec3 u = (facet.corners[1] - facet.corners[0]).normalized();
  const Vec3 v = facet.normal.cross(u);
  Vec2 lo(std::numeric_limits<double>::max(), std::numeric_limits<double>::max()), hi = -lo;
  for (const Vec3& q : facet.corners) {
    const Vec2 f((q - facet.corners[0]).dot(u), (q - facet.corners[0]).dot(v));
    lo = lo.cwiseMin(f);
    hi = hi.cwiseMax(f);
  }
  const Vec2 e = hi - lo;
  return {e.minCoeff(), e.maxCoeff()};
}

}  // namespace

std::vector<PrismFacet> prism_facets(const PrismSolution& prism) {
  const std::vector<Vec3>& p = prism.profile;
  const size_t n = p.size();
  const Vec3 axis = prism.extrusion.normalized();
  // The profile's orientation about the extrusion (Newell's normal).
  Vec3 newell = Vec3::Zero();
  for (size_t i = 0; i < n; ++i) newell += p[i].cross(p[(i + 1) % n]);
  const bool counter_clockwise = newell.dot(axis) > 0;  // seen from the far cap's side
  std::vector<PrismFacet> out(2);
  for (size_t i = 0; i < n; ++i) {
    // Seen from outside the profile cap (against the extrusion) the order reverses.
    out[0].corners.push_back(counter_clockwise ? p[n - 1 - i] : p[i]);
    out[1].corners.push_back((counter_clockwise ? p[i] : p[n - 1 - i]) + prism.extrusion);
  }
  out[0].normal = -axis;
  out[1].normal = axis;
  for (size_t i = 0; i < n; ++i) {
    const Vec3 a = p[i], b = p[(i + 1) % n];
    const Vec3 outward = (counter_clockwise ? 1.0 : -1.0) * (b - a).cross(axis).normalized();
    PrismFacet side;
    side.corners = counter_clockwise
                       ? std::vector<Vec3>{a, b, b + prism.extrusion, a + prism.extrusion}
                       : std::vector<Vec3>{b, a, a + prism.extrusion, b + prism.extrusion};
    side.normal = outward;
    out.push_back(std::move(side));
  }
  return out;
}

std::vector<bool> visible_facets(const std::vector<PrismFacet>& facets) {
  std::vector<bool> visible;
  for (const PrismFacet& facet : facets) {
    const Vec3 centre = mean(facet.corners);  // the ray: t * centre, t in (0, 1]
    bool hit_first = true;
    for (const PrismFacet& other : facets) {
      if (&other == &facet) continue;
      const double along = other.normal.dot(centre);
      if (std::abs(along) < 1e-15) continue;  // the ray runs along its plane
      const double t = other.normal.dot(other.corners[0]) / along;
      if (t > 1e-9 && t < 1 - 1e-9 && inside(other, t * centre)) hit_first = false;
    }
    visible.push_back(hit_first);
  }
  return visible;
}

std::vector<int> texture_sources(const std::vector<PrismFacet>& facets,
                                 const std::vector<bool>& visible) {
  const double parallel = std::cos(std::numbers::pi / 180);
  std::vector<int> out;
  for (size_t i = 0; i < facets.size(); ++i) {
    if (visible[i]) {
      out.push_back(int(i));
      continue;
    }
    int best = -1;
    double best_difference = std::numeric_limits<double>::max();
    for (size_t j = 0; j < facets.size(); ++j) {
      if (!visible[j] || std::abs(facets[i].normal.dot(facets[j].normal)) < parallel) continue;
      const double difference = (extents(facets[i]) - extents(facets[j])).cwiseAbs().sum();
      if (difference < best_difference) best = int(j), best_difference = difference;
    }
    out.push_back(best);
  }
  return out;
}

}  // namespace maquette::structures
