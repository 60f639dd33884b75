#include "core/polygon_set.h"

#include <algorithm>

namespace maquette {
namespace {

constexpr size_t kMaxBands = 4096;

// Whether the ray from p towards east crosses the edge a b (half-open in latitude, so a ray
// through a vertex counts it once).
bool crosses(LonLat a, LonLat b, LonLat p) {
  return (a.lat > p.lat) != (b.lat > p.lat) &&
         p.lon < (b.lon - a.lon) * (p.lat - a.lat) / (b.lat - a.lat) + a.lon;
}

// Calls edge(a, b) for every edge of the polygon's rings, each ring closed.
template <class F>
void for_each_edge(const PolygonRings& polygon, F&& edge) {
  for (const auto& ring : polygon)
    for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) edge(ring[i], ring[j]);
}

}  // namespace

bool polygon_contains(const PolygonRings& polygon, LonLat p) {
  bool inside = false;
  for_each_edge(polygon, [&](LonLat a, LonLat b) { inside ^= crosses(a, b, p); });
  return inside;
}

size_t PolygonSet::Banded::band(double lat) const {
  // Monotonic in lat. NaN at the south edge of a polygon whose extent is so small (subnormal)
  // that bands_per_degree is infinite (0 * inf): band 0, as NaN must not be converted.
  const double k = (lat - south) * bands_per_degree;
  return size_t(k > 0 ? std::min(k, double(first.size() - 2)) : 0.0);
}

PolygonSet::PolygonSet(const std::vector<PolygonRings>& polygons) {
  for (const PolygonRings& polygon : polygons) {
    Banded b{1e300, 1e300, -1e300, -1e300, 0, {}, {}};
    std::vector<Edge> edges;  // those that can cross a ray: not horizontal
    for_each_edge(polygon, [&](LonLat p, LonLat q) {
      b.west = std::min({b.west, p.lon, q.lon});
      b.east = std::max({b.east, p.lon, q.lon});
      b.south = std::min({b.south, p.lat, q.lat});
      b.north = std::max({b.north, p.lat, q.lat});
      if (p.lat != q.lat) edges.push_back({p, q});
    });
    if (edges.empty()) continue;  // no area
    const size_t bands = std::min(edges.size(), kMaxBands);
    b.bands_per_degree = double(bands) / (b.north - b.south);
    b.first.assign(bands + 1, 0);
    // Each edge goes to every band its latitudes span (counted, then placed).
    const auto span = [&](const Edge& e) {
      return std::pair(b.band(std::min(e.a.lat, e.b.lat)), b.band(std::max(e.a.lat, e.b.lat)));
    };
    std::vector<uint32_t> count(bands, 0);
    for (const Edge& e : edges)
      for (auto [lo, hi] = span(e); lo <= hi; ++lo) ++count[lo];
    for (size_t k = 0; k < bands; ++k) b.first[k + 1] = b.first[k] + count[k];
    b.edges.resize(b.first[bands]);
    std::vector<uint32_t> next(b.first.begin(), b.first.end() - 1);
    for (const Edge& e : edges)
      for (auto [lo, hi] = span(e); lo <= hi; ++lo) b.edges[next[lo]++] = e;
    polygons_.push_back(std::move(b));
  }
}

bool PolygonSet::contains(LonLat p) const {
  for (const Banded& b : polygons_) {
    if (!(p.lon >= b.west && p.lon <= b.east && p.lat >= b.south && p.lat <= b.north)) continue;
    const size_t k = b.band(p.lat);
    bool inside = false;
    for (uint32_t i = b.first[k]; i < b.first[k + 1]; ++i)
      inside ^= crosses(b.edges[i].a, b.edges[i].b, p);
    if (inside) return true;
  }
  return false;
}

}  // namespace maquette
