#include "roof_surface.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <string>
#include <tuple>
#include <utility>

#include "roof_triangulation.h"

namespace maquette::structures {
namespace {

// Points of several creases closer than this (m) are one: the same point reached by two
// computations (a hip's end from the ridge's side and from the hip's).
constexpr double kWeldM = 1e-8;

double twice_area(const PlanePoint2& a, const PlanePoint2& b, const PlanePoint2& c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

double squared_distance(const PlanePoint2& a, const PlanePoint2& b) {
  return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]);
}

// Cuts convex polygons (of point indices) by the regions where each plane is the lowest, adding
// the crease points to `points`.
class Cutter {
 public:
  Cutter(const std::vector<RoofPlane>& planes, std::vector<PlanePoint2>& points)
      : planes_(planes), points_(points) {}

  // The part of `polygon` where plane i is the lowest: clipped by each other plane's crease.
  std::vector<uint32_t> region(std::vector<uint32_t> polygon, size_t i) {
    for (size_t j = 0; j < planes_.size() && polygon.size() >= 3; ++j)
      if (j != i) polygon = clip(polygon, i, j);
    return polygon;
  }

 private:
  // The signed distance (m) of point k from the crease of planes i and j: negative where i is
  // the lower; +-infinity for parallel planes (never a crease).
  double side(uint32_t k, size_t i, size_t j) const {
    const RoofPlane &p = planes_[i], &q = planes_[j];
    const double da = p.a - q.a, db = p.b - q.b;
    const double d = da * points_[k][0] + db * points_[k][1] + (p.c - q.c);
    const double norm = std::hypot(da, db);
    if (norm > 0) return d / norm;
    return d > 0 ? INFINITY : -INFINITY;
  }

  // -1: plane i lower, 1: higher, 0: on the crease (within kCreaseSnapM).
  int state(uint32_t k, size_t i, size_t j) const {
    const double s = side(k, i, j);
    return s < -kCreaseSnapM ? -1 : s > kCreaseSnapM ? 1 : 0;
  }

  // Where the crease of i and j crosses the segment of points p and q (on either side of it):
  // computed once, from the lower-numbered point and plane, whichever polygon asks.
  uint32_t crossing(uint32_t p, uint32_t q, size_t i, size_t j) {
    if (p > q) std::swap(p, q);
    if (i > j) std::swap(i, j);
    const auto [it, added] = crossings_.try_emplace({p, q, i, j}, uint32_t(points_.size()));
    if (added) {
      const double sp = side(p, i, j), sq = side(q, i, j);
      const double t = sp / (sp - sq);
      const PlanePoint2 a = points_[p], b = points_[q];
      points_.push_back({a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])});
    }
    return it->second;
  }

  // Sutherland-Hodgman against the half-plane where i is not above j; a point on the crease
  // is kept, and no crossing is made next to it. A polygon wholly on the crease (a thin triangle
  // along it) goes to the lower-numbered plane only, not to both.
  std::vector<uint32_t> clip(const std::vector<uint32_t>& polygon, size_t i, size_t j) {
    std::vector<int> states;
    for (const uint32_t p : polygon) states.push_back(state(p, i, j));
    if (std::all_of(states.begin(), states.end(), [](int s) { return s == 0; }))
      return i < j ? polygon : std::vector<uint32_t>{};
    std::vector<uint32_t> out;
    const size_t n = polygon.size();
    for (size_t k = 0; k < n; ++k) {
      const uint32_t p = polygon[k], q = polygon[(k + 1) % n];
      const int sp = states[k], sq = states[(k + 1) % n];
      if (sq <= 0) {
        if (sp > 0 && sq < 0) out.push_back(crossing(p, q, i, j));
        out.push_back(q);
      } else if (sp < 0) {
        out.push_back(crossing(p, q, i, j));
      }
    }
    return out;
  }

  const std::vector<RoofPlane>& planes_;
  std::vector<PlanePoint2>& points_;
  std::map<std::tuple<uint32_t, uint32_t, size_t, size_t>, uint32_t> crossings_;
};

// The points where three planes meet as the lowest (a hip's end, a pyramid's apex): where most
// creases pass a point, cutting triangles line by line would leave crossings millimetres apart.
std::vector<PlanePoint2> corners(const std::vector<RoofPlane>& planes) {
  std::vector<PlanePoint2> out;
  for (size_t i = 0; i < planes.size(); ++i)
    for (size_t j = i + 1; j < planes.size(); ++j)
      for (size_t k = j + 1; k < planes.size(); ++k) {
        const RoofPlane &p = planes[i], &q = planes[j], &r = planes[k];
        const double a = p.a - q.a, b = p.b - q.b, c = p.a - r.a, d = p.b - r.b;
        const double det = a * d - b * c;
        if (det == 0) continue;
        const double e = q.c - p.c, f = r.c - p.c;
        const PlanePoint2 x{(e * d - b * f) / det, (a * f - e * c) / det};
        double lowest = INFINITY;
        for (const RoofPlane& plane : planes) lowest = std::min(lowest, plane.at(x));
        const bool seen = std::any_of(out.begin(), out.end(), [&](const PlanePoint2& o) {
          return squared_distance(o, x) <= kWeldM * kWeldM;
        });
        if (p.at(x) <= lowest + 1e-9 * (1 + std::abs(lowest)) && !seen) out.push_back(x);
      }
  return out;
}

// Inserts point `q` into the triangles (counter-clockwise, indices into points): in the one
// holding it, split in three, or, within kCreaseSnapM of an edge, onto that edge (moved there),
// both triangles beside it split in two. Nothing when it is outside them or at a corner.
void insert_point(std::vector<uint32_t>& triangles, std::vector<PlanePoint2>& points,
                  PlanePoint2 q) {
  size_t best = 0;
  std::array<double, 3> distance{};
  double inside = -INFINITY;
  for (size_t t = 0; t < triangles.size(); t += 3) {
    std::array<double, 3> d{};
    for (size_t k = 0; k < 3; ++k) {
      const PlanePoint2 &a = points[triangles[t + k]], &b = points[triangles[t + (k + 1) % 3]];
      d[k] = twice_area(a, b, q) / std::sqrt(squared_distance(a, b));
    }
    if (const double least = std::min({d[0], d[1], d[2]}); least > inside)
      inside = least, best = t, distance = d;
  }
  if (inside < -kCreaseSnapM) return;
  int on = 0, edge = 0;
  for (int k = 0; k < 3; ++k)
    if (distance[size_t(k)] <= kCreaseSnapM) ++on, edge = k;
  if (on > 1) return;
  const uint32_t n = uint32_t(points.size());
  const std::array<uint32_t, 3> v = {triangles[best + size_t(edge)],
                                     triangles[best + size_t(edge + 1) % 3],
                                     triangles[best + size_t(edge + 2) % 3]};
  if (on == 0) {
    points.push_back(q);
    std::copy_n(std::array{v[0], v[1], n}.begin(), 3, triangles.begin() + long(best));
    triangles.insert(triangles.end(), {v[1], v[2], n, v[2], v[0], n});
    return;
  }
  // Onto the edge v0-v1, opposite v2; the triangle beside it has the edge v1-v0.
  const PlanePoint2 &a = points[v[0]], &b = points[v[1]];
  const double t =
      ((q[0] - a[0]) * (b[0] - a[0]) + (q[1] - a[1]) * (b[1] - a[1])) / squared_distance(a, b);
  points.push_back({a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])});
  std::copy_n(std::array{v[0], n, v[2]}.begin(), 3, triangles.begin() + long(best));
  triangles.insert(triangles.end(), {n, v[1], v[2]});
  for (size_t u = 0; u < triangles.size(); u += 3)
    for (size_t k = 0; k < 3; ++k)
      if (triangles[u + k] == v[1] && triangles[u + (k + 1) % 3] == v[0]) {
        const uint32_t w = triangles[u + (k + 2) % 3];
        std::copy_n(std::array{v[1], n, w}.begin(), 3, triangles.begin() + long(u));
        triangles.insert(triangles.end(), {n, v[0], w});
        return;
      }
}

// Each added point (from `first`) mapped to the lowest-numbered point within kWeldM of it.
std::vector<uint32_t> welded(const std::vector<PlanePoint2>& points, uint32_t first) {
  std::vector<uint32_t> parent(points.size());
  std::iota(parent.begin(), parent.end(), 0u);
  const auto find = [&](uint32_t k) {
    while (parent[k] != k) k = parent[k] = parent[parent[k]];
    return k;
  };
  std::vector<uint32_t> order(points.size() - first);
  std::iota(order.begin(), order.end(), first);
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
    return std::tie(points[a][0], a) < std::tie(points[b][0], b);
  });
  for (size_t a = 0; a < order.size(); ++a)
    for (size_t b = a + 1; b < order.size() && points[order[b]][0] - points[order[a]][0] <= kWeldM;
         ++b)
      if (squared_distance(points[order[a]], points[order[b]]) <= kWeldM * kWeldM) {
        const uint32_t ra = find(order[a]), rb = find(order[b]);
        parent[std::max(ra, rb)] = std::min(ra, rb);
      }
  for (uint32_t k = 0; k < parent.size(); ++k) parent[k] = find(k);
  return parent;
}

// The triangles of a convex, counter-clockwise polygon: a fan from its first point, or, when
// three consecutive points are in line (a crease point on a side), from a point added at its
// vertex centroid (a fan from a corner would give triangles of no area). Nothing for a polygon
// of no area.
void triangulate_convex(const std::vector<uint32_t>& polygon, std::vector<PlanePoint2>& points,
                        std::vector<uint32_t>& triangles) {
  const size_t n = polygon.size();
  double longest = 0, twice = 0;
  for (size_t k = 0; k < n; ++k) {
    const PlanePoint2 &p = points[polygon[k]], &q = points[polygon[(k + 1) % n]];
    longest = std::max(longest, squared_distance(p, q));
    twice += p[0] * q[1] - q[0] * p[1];
  }
  const double in_line = 1e-9 * longest;
  if (!(twice > in_line)) return;
  bool straight = false;
  for (size_t k = 0; k < n && !straight; ++k)
    straight = std::abs(twice_area(points[polygon[(k + n - 1) % n]], points[polygon[k]],
                                   points[polygon[(k + 1) % n]])) <= in_line;
  if (!straight) {
    for (size_t k = 1; k + 1 < n; ++k)
      triangles.insert(triangles.end(), {polygon[0], polygon[k], polygon[k + 1]});
    return;
  }
  PlanePoint2 centre{0, 0};
  for (const uint32_t k : polygon)
    centre = {centre[0] + points[k][0] / double(n), centre[1] + points[k][1] / double(n)};
  const uint32_t c = uint32_t(points.size());
  points.push_back(centre);
  for (size_t k = 0; k < n; ++k)
    triangles.insert(triangles.end(), {c, polygon[k], polygon[(k + 1) % n]});
}

// The rings as the triangles' boundary: each boundary edge's successor, walked from each ring's
// first point.
std::vector<std::vector<uint32_t>> outline_of(const RoofSurface& s, const Footprint& footprint) {
  std::vector<std::pair<uint32_t, uint32_t>> edges;
  for (const std::vector<uint32_t>& face : s.faces)
    for (size_t t = 0; t < face.size(); t += 3)
      for (size_t k = 0; k < 3; ++k) edges.emplace_back(face[t + k], face[t + (k + 1) % 3]);
  std::sort(edges.begin(), edges.end());
  std::vector<int64_t> next(s.points.size(), -1);
  size_t boundary = 0;
  for (const auto& [a, b] : edges)
    if (!std::binary_search(edges.begin(), edges.end(), std::make_pair(b, a))) {
      if (next[a] >= 0) throw InvalidFootprint("the roof's pieces meet at a point of the outline");
      next[a] = b;
      ++boundary;
    }
  std::vector<std::vector<uint32_t>> outline;
  uint32_t start = 0;
  for (const PlaneRing& ring : footprint.rings) {
    std::vector<uint32_t>& walked = outline.emplace_back();
    for (uint32_t k = start; walked.empty() || k != start; k = uint32_t(next[k])) {
      if (next[k] < 0 || walked.size() > boundary)
        throw InvalidFootprint("the roof's pieces do not close around ring " +
                               std::to_string(outline.size() - 1));
      walked.push_back(k);
    }
    start += uint32_t(ring.size());
    boundary -= walked.size();
  }
  if (boundary != 0) throw InvalidFootprint("the roof's pieces leave a gap inside the footprint");
  return outline;
}

// Drops the added points no triangle uses, renumbering the others.
void drop_unused(RoofSurface& s, uint32_t first) {
  std::vector<bool> used(s.points.size(), false);
  for (const std::vector<uint32_t>& face : s.faces)
    for (const uint32_t k : face) used[k] = true;
  std::vector<uint32_t> index(s.points.size());
  std::iota(index.begin(), index.begin() + first, 0u);
  uint32_t next = first;
  for (uint32_t k = first; k < s.points.size(); ++k)
    if (used[k]) {
      index[k] = next;
      s.points[next++] = s.points[k];
    }
  s.points.resize(next);
  for (std::vector<uint32_t>& face : s.faces)
    for (uint32_t& k : face) k = index[k];
}

}  // namespace

double RoofSurface::volume() const {
  double sum = 0;
  for (const std::vector<uint32_t>& face : faces)
    for (size_t t = 0; t < face.size(); t += 3)
      sum += twice_area(points[face[t]], points[face[t + 1]], points[face[t + 2]]) *
             (heights[face[t]] + heights[face[t + 1]] + heights[face[t + 2]]);
  return sum / 6;
}

RoofSurface roof_surface(const Footprint& footprint, const std::vector<RoofPlane>& planes) {
  RoofSurface s;
  for (const PlaneRing& ring : footprint.rings) {
    std::vector<uint32_t>& indices = s.outline.emplace_back();
    for (const PlanePoint2& p : ring) {
      indices.push_back(uint32_t(s.points.size()));
      s.points.push_back(p);
    }
  }
  const uint32_t first_added = uint32_t(s.points.size());
  std::vector<uint32_t> triangles = triangulate_footprint(footprint);
  if (planes.size() == 1) {
    s.faces.push_back(std::move(triangles));
  } else {
    for (const PlanePoint2& corner : corners(planes)) insert_point(triangles, s.points, corner);
    Cutter cutter(planes, s.points);
    std::vector<std::pair<size_t, std::vector<uint32_t>>> pieces;
    for (size_t t = 0; t < triangles.size(); t += 3)
      for (size_t i = 0; i < planes.size(); ++i)
        if (std::vector<uint32_t> piece =
                cutter.region({triangles[t], triangles[t + 1], triangles[t + 2]}, i);
            piece.size() >= 3)
          pieces.emplace_back(i, std::move(piece));
    const std::vector<uint32_t> same = welded(s.points, first_added);
    std::vector<std::vector<uint32_t>> faces(planes.size());
    for (auto& [plane, piece] : pieces) {
      for (uint32_t& k : piece) k = same[k];
      piece.erase(std::unique(piece.begin(), piece.end()), piece.end());
      while (piece.size() > 1 && piece.back() == piece.front()) piece.pop_back();
      if (piece.size() >= 3) triangulate_convex(piece, s.points, faces[plane]);
    }
    for (std::vector<uint32_t>& face : faces)
      if (!face.empty()) s.faces.push_back(std::move(face));
    drop_unused(s, first_added);
    s.outline = outline_of(s, footprint);
  }
  s.heights.reserve(s.points.size());
  for (const PlanePoint2& p : s.points) {
    double lowest = INFINITY;
    for (const RoofPlane& plane : planes) lowest = std::min(lowest, plane.at(p));
    s.heights.push_back(lowest);
  }
  return s;
}

}  // namespace maquette::structures
