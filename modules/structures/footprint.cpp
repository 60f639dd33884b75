#include "footprint.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace maquette::structures {
namespace {

double cross(const PlanePoint2& o, const PlanePoint2& a, const PlanePoint2& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

int sign(double v) { return (v > 0) - (v < 0); }

// Whether p, collinear with segment ab, lies on it.
bool on_segment(const PlanePoint2& a, const PlanePoint2& b, const PlanePoint2& p) {
  return std::min(a[0], b[0]) <= p[0] && p[0] <= std::max(a[0], b[0]) &&
         std::min(a[1], b[1]) <= p[1] && p[1] <= std::max(a[1], b[1]);
}

// Closed segments ab and cd share a point.
bool segments_meet(const PlanePoint2& a, const PlanePoint2& b, const PlanePoint2& c,
                   const PlanePoint2& d) {
  const int o1 = sign(cross(a, b, c)), o2 = sign(cross(a, b, d));
  const int o3 = sign(cross(c, d, a)), o4 = sign(cross(c, d, b));
  if (o1 != o2 && o3 != o4) return true;
  return (o1 == 0 && on_segment(a, b, c)) || (o2 == 0 && on_segment(a, b, d)) ||
         (o3 == 0 && on_segment(c, d, a)) || (o4 == 0 && on_segment(c, d, b));
}

// Crossing-number test; p must not lie on the ring (edges do not touch once checked).
bool inside(const PlaneRing& ring, const PlanePoint2& p) {
  bool in = false;
  for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++)
    if ((ring[i][1] > p[1]) != (ring[j][1] > p[1]) &&
        p[0] < ring[j][0] +
                   (p[1] - ring[j][1]) / (ring[i][1] - ring[j][1]) * (ring[i][0] - ring[j][0]))
      in = !in;
  return in;
}

std::string ring_name(size_t k) { return k == 0 ? "the outer ring" : "hole " + std::to_string(k); }

// Inside the footprint's area: in its outer ring, in none of its holes.
bool on_area(const Footprint& fp, const PlanePoint2& p) {
  if (!inside(fp.rings[0], p)) return false;
  for (size_t k = 1; k < fp.rings.size(); ++k)
    if (inside(fp.rings[k], p)) return false;
  return true;
}

std::string point_text(const PlanePoint2& p) {
  std::ostringstream s;
  s.precision(3);
  s << std::fixed << "(" << p[0] << " m E, " << p[1] << " m N)";
  return s.str();
}

void drop_repeats(PlaneRing& ring) {
  ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
  while (ring.size() > 1 && ring.back() == ring.front()) ring.pop_back();
}

struct Edge {
  size_t ring, index;  // from point `index` to the next of its ring
};

// Edges e and f (e before f in ring order) are neighbours in one ring: they share a point, and
// meet elsewhere only when they fold back onto each other.
bool neighbours_fold(const std::vector<PlaneRing>& rings, const Edge& e, const Edge& f) {
  const PlaneRing& r = rings[e.ring];
  const size_t n = r.size();
  // The shared point s, e's other end a, f's other end b.
  const bool f_follows = f.index == (e.index + 1) % n;
  const PlanePoint2& s = f_follows ? r[f.index] : r[e.index];
  const PlanePoint2& a = f_follows ? r[e.index] : r[(e.index + 1) % n];
  const PlanePoint2& b = f_follows ? r[(f.index + 1) % n] : r[f.index];
  return cross(s, a, b) == 0 && (a[0] - s[0]) * (b[0] - s[0]) + (a[1] - s[1]) * (b[1] - s[1]) > 0;
}

void check_edges(const std::vector<PlaneRing>& rings) {
  std::vector<Edge> edges;
  for (size_t k = 0; k < rings.size(); ++k)
    for (size_t i = 0; i < rings[k].size(); ++i) edges.push_back({k, i});
  const auto end = [&](const Edge& e, int which) -> const PlanePoint2& {
    const PlaneRing& r = rings[e.ring];
    return r[(e.index + size_t(which)) % r.size()];
  };
  for (size_t i = 0; i < edges.size(); ++i)
    for (size_t j = i + 1; j < edges.size(); ++j) {
      const Edge& e = edges[i];
      const Edge& f = edges[j];
      const size_t n = rings[e.ring].size();
      const bool adjacent =
          e.ring == f.ring && (f.index == (e.index + 1) % n || e.index == (f.index + 1) % n);
      const bool meet = adjacent ? neighbours_fold(rings, e, f)
                                 : segments_meet(end(e, 0), end(e, 1), end(f, 0), end(f, 1));
      if (meet)
        throw InvalidFootprint(ring_name(e.ring) + "'s edge from " + point_text(end(e, 0)) +
                               (adjacent ? " folds back onto " : " meets ") + ring_name(f.ring) +
                               "'s edge from " + point_text(end(f, 0)));
    }
}

}  // namespace

double signed_area(const PlaneRing& ring) {
  double twice = 0;
  for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++)
    twice += (ring[j][0] - ring[i][0]) * (ring[j][1] + ring[i][1]);
  return twice / 2;
}

Footprint make_footprint(std::vector<PlaneRing> rings) {
  if (rings.empty()) throw InvalidFootprint("the polygon has no ring");
  Footprint fp;
  for (size_t k = 0; k < rings.size(); ++k) {
    PlaneRing& ring = rings[k];
    drop_repeats(ring);
    if (ring.size() < 3)
      throw InvalidFootprint(ring_name(k) + " has " + std::to_string(ring.size()) +
                             " distinct points, fewer than 3");
    const double area = signed_area(ring);
    if (std::abs(area) < kMinRingAreaM2) {
      std::ostringstream s;
      s << ring_name(k) << " has an area of " << std::abs(area) << " m2, below " << kMinRingAreaM2
        << " m2";
      throw InvalidFootprint(s.str());
    }
    // Outer counter-clockwise, holes clockwise, keeping the first point first.
    if ((area > 0) != (k == 0)) std::reverse(ring.begin() + 1, ring.end());
    fp.area += k == 0 ? std::abs(area) : -std::abs(area);
  }
  check_edges(rings);
  for (size_t k = 1; k < rings.size(); ++k) {
    if (!inside(rings[0], rings[k][0]))
      throw InvalidFootprint(ring_name(k) + " lies outside the outer ring");
    for (size_t m = 1; m < rings.size(); ++m)
      if (m != k && inside(rings[m], rings[k][0]))
        throw InvalidFootprint(ring_name(k) + " lies inside " + ring_name(m));
  }
  fp.rings = std::move(rings);
  return fp;
}

void check_disjoint(const std::vector<Footprint>& parts) {
  std::vector<PlaneRing> rings;
  for (const Footprint& part : parts)
    rings.insert(rings.end(), part.rings.begin(), part.rings.end());
  try {
    check_edges(rings);
  } catch (const InvalidFootprint& e) {
    throw InvalidFootprint(std::string("two parts meet: ") + e.what() +
                           " (rings numbered across the parts)");
  }
  for (size_t k = 0; k < parts.size(); ++k)
    for (size_t m = 0; m < parts.size(); ++m)
      if (m != k && on_area(parts[m], parts[k].rings[0][0]))
        throw InvalidFootprint("part " + std::to_string(k) + " lies on part " + std::to_string(m));
}

}  // namespace maquette::structures
