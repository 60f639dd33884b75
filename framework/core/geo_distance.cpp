#include "core/geo_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/polygon_set.h"

namespace maquette {
namespace {

using Segment = std::array<Vec3, 2>;

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3 along(const Vec3& a, const Vec3& d, double t) {
  return {a[0] + t * d[0], a[1] + t * d[1], a[2] + t * d[2]};
}
double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }

// Shortest distance between segments p0-p1 and q0-q1 (either may be a point): the closest
// points by clamped parameters (Ericson, Real-Time Collision Detection, 5.1.9).
double segment_distance(const Segment& p, const Segment& q) {
  const Vec3 d1 = sub(p[1], p[0]), d2 = sub(q[1], q[0]), r = sub(p[0], q[0]);
  const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
  double s = 0, t = 0;
  if (a == 0 && e == 0) return norm(r);
  if (a == 0) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = dot(d1, r);
    if (e == 0) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = dot(d1, d2), denom = a * e - b * b;
      s = denom > 0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0) {
        t = 0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1) {
        t = 1;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  return norm(sub(along(p[0], d1, s), along(q[0], d2, t)));
}

Vec3 position(const GeoPoint& p) { return ecef({p.lon, p.lat}); }

// A path's edges cut into pieces of at most kPieceDegrees, as ECEF segments (a path of one
// point: one segment of length 0).
void add_pieces(const GeoPath& path, std::vector<Segment>& out) {
  if (path.size() == 1) out.push_back({position(path[0]), position(path[0])});
  for (size_t i = 1; i < path.size(); ++i) {
    const GeoPoint& a = path[i - 1];
    const GeoPoint& b = path[i];
    const int n = std::max(
        1,
        int(std::ceil(std::max(std::abs(b.lon - a.lon), std::abs(b.lat - a.lat)) / kPieceDegrees)));
    Vec3 from = position(a);
    for (int k = 1; k <= n; ++k) {
      const double t = double(k) / n;
      const Vec3 to =
          k == n ? position(b) : ecef({a.lon + t * (b.lon - a.lon), a.lat + t * (b.lat - a.lat)});
      out.push_back({from, to});
      from = to;
    }
  }
}

std::vector<Segment> pieces(const Geometry& g) {
  std::vector<Segment> out;
  for (const GeoPoint& p : g.points) add_pieces({p}, out);
  for (const GeoPath& line : g.lines) add_pieces(line, out);
  for (const GeoPolygon& polygon : g.polygons)
    for (const GeoPath& ring : polygon.rings) add_pieces(ring, out);
  return out;
}

bool in_polygon(const Geometry& g, LonLat p) {
  for (const GeoPolygon& polygon : g.polygons) {
    PolygonRings rings;
    for (const GeoPath& ring : polygon.rings) {
      auto& r = rings.emplace_back();
      for (const GeoPoint& q : ring) r.push_back({q.lon, q.lat});
    }
    if (polygon_contains(rings, p)) return true;
  }
  return false;
}

// Whether two chords cross as seen from above (projected along the vertical at their first
// point): two edges that cross on the ground have chords that pass a few millimetres apart in 3D
// (skew lines), which must count as meeting (distance 0), not as a gap.
bool cross_from_above(const Segment& p, const Segment& q) {
  const Vec3& up = p[0];
  auto side = [&](const Vec3& a, const Vec3& b, const Vec3& c) {
    return dot(cross(sub(b, a), sub(c, a)), up);
  };
  const double d1 = side(p[0], p[1], q[0]), d2 = side(p[0], p[1], q[1]);
  const double d3 = side(q[0], q[1], p[0]), d4 = side(q[0], q[1], p[1]);
  return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

// The most a chord of `segments` lies below the surface it spans: L^2 / (8 R) for the longest,
// R = 6335 km (the ellipsoid's smallest radius of curvature).
double largest_sag(const std::vector<Segment>& segments) {
  double longest = 0;
  for (const Segment& s : segments) longest = std::max(longest, norm(sub(s[1], s[0])));
  return longest * longest / (8 * 6.335e6);
}

// The shortest distance between segments `a` (within `radius` of `centre`) and `b`; segments of
// `b` whose lower bound exceeds the best so far are skipped. 0 when two cross from above: chords
// of edges that cross on the ground pass at most their sags apart, so pairs closer than that (and
// a metre) are tested for crossing.
double shortest(const std::vector<Segment>& a, const Vec3& centre, double radius,
                const std::vector<Segment>& b) {
  const double crossing_check_m = 1 + largest_sag(a) + largest_sag(b);
  double best = std::numeric_limits<double>::infinity();
  for (const Segment& piece : b) {
    if (segment_distance({centre, centre}, piece) - radius >= best) continue;
    for (const Segment& s : a) {
      const double d = segment_distance(s, piece);
      if (d < crossing_check_m && cross_from_above(s, piece)) return 0;
      best = std::min(best, d);
    }
  }
  return best;
}

// A sphere of radius r holding an outline, enlarged to hold the surface inside it, which bulges
// above the outline's chords by at most about r^2 / (2 R) (R >= 6335 km, the ellipsoid's
// smallest radius of curvature): twice that added.
double with_bulge(double r) { return r + r * r / 6.335e6; }

template <typename F>
void for_each_vertex(const Geometry& g, F&& f) {
  for (const GeoPoint& p : g.points) f(p);
  for (const GeoPath& line : g.lines)
    for (const GeoPoint& p : line) f(p);
  for (const GeoPolygon& polygon : g.polygons)
    for (const GeoPath& ring : polygon.rings)
      for (const GeoPoint& p : ring) f(p);
}

}  // namespace

double distance_m(LonLat p, const Geometry& g) {
  if (in_polygon(g, p)) return 0;
  const Vec3 x = ecef(p);
  return shortest({{x, x}}, x, 0, pieces(g));
}

GeometryPieces::GeometryPieces(const Geometry& g) : geometry_(&g), segments_(pieces(g)) {
  if (segments_.empty()) return;
  for (const Segment& s : segments_)
    for (int k = 0; k < 3; ++k) centre_[k] += s[0][k] / double(segments_.size());
  for (const Segment& s : segments_)
    radius_ = std::max({radius_, norm(sub(s[0], centre_)), norm(sub(s[1], centre_))});
  if (!g.polygons.empty()) radius_ = with_bulge(radius_);
}

CellOutline::CellOutline(const Grid& grid, CellId cell)
    : grid_(&grid), cell_(cell), centre_lonlat_(grid.centre(cell)), centre_(ecef(centre_lonlat_)) {
  const double side = grid.level_info(cell.level(), 1).plane_side_m;
  const int points = std::clamp(int(std::ceil(side / kOutlineSpacingM)), 1, 1024);
  const std::vector<LonLat> ring = grid.boundary(cell, points);
  Vec3 from = ecef(ring.front());
  for (size_t i = 1; i < ring.size(); ++i) {
    const Vec3 to = ecef(ring[i]);
    sides_.push_back({from, to});
    radius_ = std::max(radius_, norm(sub(to, centre_)));
    from = to;
  }
  radius_ = with_bulge(radius_);
}

double CellOutline::distance_m(const GeometryPieces& g) const {
  bool inside = in_polygon(g.geometry(), centre_lonlat_);
  for_each_vertex(g.geometry(), [&](const GeoPoint& p) {
    inside = inside || grid_->cell_from_point({p.lon, p.lat}, cell_.level()) == cell_;
  });
  return inside ? 0 : shortest(sides_, centre_, radius_, g.segments());
}

double sphere_gap_m(const Vec3& a, double radius_a, const Vec3& b, double radius_b) {
  return norm(sub(a, b)) - radius_a - radius_b;
}

}  // namespace maquette
