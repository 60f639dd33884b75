#include "lonlat_polygon.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"

namespace maquette {
namespace {

constexpr double kShifts[] = {-360, 0, 360};

bool overlaps(double lo, double hi, double a, double b) { return a <= hi && b >= lo; }

// Twice the signed area of the triangle a b c: > 0 when c is left of a -> b.
double orient(LonLat a, LonLat b, LonLat c) {
  return (b.lon - a.lon) * (c.lat - a.lat) - (b.lat - a.lat) * (c.lon - a.lon);
}

// Whether the closed segments a b and c d meet (touching counts).
bool segments_meet(LonLat a, LonLat b, LonLat c, LonLat d) {
  if (std::max(a.lon, b.lon) < std::min(c.lon, d.lon) ||
      std::max(c.lon, d.lon) < std::min(a.lon, b.lon) ||
      std::max(a.lat, b.lat) < std::min(c.lat, d.lat) ||
      std::max(c.lat, d.lat) < std::min(a.lat, b.lat)) {
    return false;
  }
  const double d1 = orient(a, b, c), d2 = orient(a, b, d);
  if (d1 == 0 && d2 == 0) return true;  // collinear, and the bounding boxes overlap
  const double d3 = orient(c, d, a), d4 = orient(c, d, b);
  return !((d1 > 0 && d2 > 0) || (d1 < 0 && d2 < 0) || (d3 > 0 && d4 > 0) || (d3 < 0 && d4 < 0));
}

// Crossing number of p against the closed ring shifted by `shift` in longitude.
bool in_ring(std::span<const LonLat> ring, double shift, LonLat p) {
  bool inside = false;
  for (size_t i = 0; i + 1 < ring.size(); ++i) {
    const LonLat a = ring[i], b = ring[i + 1];
    if ((a.lat > p.lat) != (b.lat > p.lat) &&
        p.lon < a.lon + shift + (p.lat - a.lat) / (b.lat - a.lat) * (b.lon - a.lon)) {
      inside = !inside;
    }
  }
  return inside;
}

}  // namespace

LonLatPolygon::LonLatPolygon(const std::vector<std::vector<LonLat>>& rings) {
  if (rings.empty()) throw Error("invalid polygon: no rings");
  bounds_ = {1e300, 90, -1e300, -90};
  for (size_t i = 0; i < rings.size(); ++i) {
    std::vector<LonLat> ring = rings[i];
    if (ring.size() > 1 && ring.front().lon == ring.back().lon &&
        ring.front().lat == ring.back().lat) {
      ring.pop_back();
    }
    if (ring.size() < 3) {
      throw Error("invalid polygon: ring " + std::to_string(i) + " has " +
                  std::to_string(ring.size()) + " distinct points, expected at least 3");
    }
    for (size_t j = 0; j < ring.size(); ++j) {
      const LonLat p = ring[j];
      if (!(p.lat >= -90 && p.lat <= 90) || !std::isfinite(p.lon)) {
        throw Error("invalid polygon point lon " + std::to_string(p.lon) + ", lat " +
                    std::to_string(p.lat) + " in ring " + std::to_string(i));
      }
      edges_.push_back({p, ring[(j + 1) % ring.size()]});
      bounds_ = {std::min(bounds_.west, p.lon), std::min(bounds_.south, p.lat),
                 std::max(bounds_.east, p.lon), std::max(bounds_.north, p.lat)};
    }
  }
}

bool LonLatPolygon::contains_unshifted(double lon, double lat) const {
  bool inside = false;
  for (const Edge& e : edges_) {
    if ((e.a.lat > lat) != (e.b.lat > lat) &&
        lon < e.a.lon + (lat - e.a.lat) / (e.b.lat - e.a.lat) * (e.b.lon - e.a.lon)) {
      inside = !inside;
    }
  }
  return inside;
}

bool LonLatPolygon::contains(LonLat p) const {
  for (const double s : kShifts) {
    const double lon = p.lon + s;
    if (lon >= bounds_.west && lon <= bounds_.east && contains_unshifted(lon, p.lat)) return true;
  }
  return false;
}

// Whether the segment meets the open rectangle: the parameters t in [0, 1] strictly inside
// both slabs form the open interval (lo, hi).
bool LonLatPolygon::crosses_interior(const Edge& e, const LonLatRect& r) const {
  double lo = -1e300;
  double hi = 1e300;
  const auto slab = [&](double p, double d, double min, double max) {
    if (d == 0) {
      if (!(p > min && p < max)) hi = lo;
      return;
    }
    const double t0 = (min - p) / d;
    const double t1 = (max - p) / d;
    lo = std::max(lo, std::min(t0, t1));
    hi = std::min(hi, std::max(t0, t1));
  };
  slab(e.a.lon, e.b.lon - e.a.lon, r.west, r.east);
  slab(e.a.lat, e.b.lat - e.a.lat, r.south, r.north);
  return lo < hi && lo < 1 && hi > 0;
}

Relation LonLatPolygon::relate(const LonLatRect& r, std::span<const uint32_t> candidates,
                               std::vector<uint32_t>& crossing) const {
  crossing.clear();
  if (!overlaps(bounds_.south, bounds_.north, r.south, r.north)) return Relation::Disjoint;
  bool inside = false;
  for (const double s : kShifts) {
    const LonLatRect shifted{r.west + s, r.south, r.east + s, r.north};
    if (!overlaps(bounds_.west, bounds_.east, shifted.west, shifted.east)) continue;
    const size_t before = crossing.size();
    for (const uint32_t i : candidates) {
      if (crosses_interior(edges_[i], shifted)) crossing.push_back(i);
    }
    if (crossing.size() > before) continue;
    // No edge meets the open rectangle: it is all inside or all outside.
    inside = inside || contains_unshifted((shifted.west + shifted.east) / 2,
                                          (shifted.south + shifted.north) / 2);
  }
  if (inside) return Relation::Inside;
  // An edge may be listed for two shifts.
  std::sort(crossing.begin(), crossing.end());
  crossing.erase(std::unique(crossing.begin(), crossing.end()), crossing.end());
  return crossing.empty() ? Relation::Disjoint : Relation::Crosses;
}

// The ring shifted by `shift` against the unshifted polygon. With no contact between the
// boundaries, each ring of the polygon lies wholly inside or wholly outside the ring (then one
// of its vertices tells, and its edges, meeting the enclosing rectangle, are candidates), and
// the ring wholly inside or outside the polygon (its first point tells).
Relation LonLatPolygon::relate_ring_shifted(std::span<const LonLat> ring, double shift,
                                            std::span<const uint32_t> candidates) const {
  for (const uint32_t i : candidates) {
    const Edge& e = edges_[i];
    for (size_t j = 0; j + 1 < ring.size(); ++j) {
      const LonLat a{ring[j].lon + shift, ring[j].lat}, b{ring[j + 1].lon + shift, ring[j + 1].lat};
      if (segments_meet(e.a, e.b, a, b)) return Relation::Crosses;
    }
  }
  for (const uint32_t i : candidates) {
    if (in_ring(ring, shift, edges_[i].a)) return Relation::Crosses;
  }
  return contains_unshifted(ring[0].lon + shift, ring[0].lat) ? Relation::Inside
                                                              : Relation::Disjoint;
}

Relation LonLatPolygon::relate_ring(std::span<const LonLat> ring,
                                    std::span<const uint32_t> candidates) const {
  LonLatRect r{1e300, 90, -1e300, -90};
  for (const LonLat& p : ring) {
    r = {std::min(r.west, p.lon), std::min(r.south, p.lat), std::max(r.east, p.lon),
         std::max(r.north, p.lat)};
  }
  if (!overlaps(bounds_.south, bounds_.north, r.south, r.north)) return Relation::Disjoint;
  bool crosses = false;
  for (const double s : kShifts) {
    if (!overlaps(bounds_.west, bounds_.east, r.west + s, r.east + s)) continue;
    const Relation relation = relate_ring_shifted(ring, s, candidates);
    if (relation == Relation::Inside) return Relation::Inside;
    crosses = crosses || relation == Relation::Crosses;
  }
  return crosses ? Relation::Crosses : Relation::Disjoint;
}

}  // namespace maquette
