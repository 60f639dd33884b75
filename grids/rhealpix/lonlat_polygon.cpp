#include "lonlat_polygon.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"

namespace maquette {
namespace {

constexpr double kShifts[] = {-360, 0, 360};

bool overlaps(double lo, double hi, double a, double b) { return a <= hi && b >= lo; }

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

}  // namespace maquette
