#include "place_stroke.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <numbers>
#include <sstream>

#include "content/enu_transform.h"
#include "core/enu_frame.h"
#include "core/error.h"

namespace maquette::structures {

namespace {

// The ring without a repeated closing point.
Ring open_ring(const Ring& ring) {
  Ring open = ring;
  if (open.size() > 1 && open.front() == open.back()) open.pop_back();
  return open;
}

// Area integrals over a polygon, as a sum over the triangles (origin, p, q) of its edges:
// integral of x^n over such a triangle is cross(p, q) * n! / (n + 2)! * sum of x_p^j x_q^(n-j)
// (barycentric monomials), whatever the ring's orientation once divided by the signed area.
struct Integrals {
  double area = 0, x = 0, y = 0, xx = 0, yy = 0, xy = 0;
};

Integrals integrals(const Ring& ring, Point2 shift) {
  Integrals s;
  for (size_t i = 0; i < ring.size(); ++i) {
    const Point2& a = ring[i];
    const Point2& b = ring[(i + 1) % ring.size()];
    const double ax = a[0] - shift[0], ay = a[1] - shift[1];
    const double bx = b[0] - shift[0], by = b[1] - shift[1];
    const double cross = ax * by - bx * ay;
    s.area += cross / 2;
    s.x += cross * (ax + bx) / 6;
    s.y += cross * (ay + by) / 6;
    s.xx += cross * (ax * ax + ax * bx + bx * bx) / 12;
    s.yy += cross * (ay * ay + ay * by + by * by) / 12;
    s.xy += cross * (2 * ax * ay + ax * by + bx * ay + 2 * bx * by) / 24;
  }
  return s;
}

// Integral of u^3 dA over the ring, u = the coordinate along unit direction (c, s) from `origin`.
double third_moment(const Ring& ring, Point2 origin, double c, double s) {
  double sum = 0;
  for (size_t i = 0; i < ring.size(); ++i) {
    const Point2& a = ring[i];
    const Point2& b = ring[(i + 1) % ring.size()];
    const double ax = a[0] - origin[0], ay = a[1] - origin[1];
    const double bx = b[0] - origin[0], by = b[1] - origin[1];
    const double ua = c * ax + s * ay, ub = c * bx + s * by;
    sum += (ax * by - bx * ay) * (ua * ua * ua + ua * ua * ub + ua * ub * ub + ub * ub * ub) / 20;
  }
  return sum;
}

// A similarity p -> [a -b; b a] p + t: rotation atan2(b, a), scale hypot(a, b).
struct Similarity {
  double a = 1, b = 0;
  Point2 t{};
  Point2 operator()(Point2 p) const {
    return {a * p[0] - b * p[1] + t[0], b * p[0] + a * p[1] + t[1]};
  }
};

// The point of the ring's outline nearest to `q`, and the unit direction from it towards q (the
// edge's outward-or-inward normal; the edge's left normal when q is on it).
struct Nearest {
  Point2 point{};
  Point2 normal{};
};

Nearest nearest_on_outline(const Ring& ring, Point2 q) {
  Nearest best;
  double best_d2 = INFINITY;
  for (size_t i = 0; i < ring.size(); ++i) {
    const Point2& a = ring[i];
    const Point2& b = ring[(i + 1) % ring.size()];
    const double ex = b[0] - a[0], ey = b[1] - a[1];
    const double len2 = ex * ex + ey * ey;
    if (len2 == 0) continue;
    const double t = std::clamp(((q[0] - a[0]) * ex + (q[1] - a[1]) * ey) / len2, 0.0, 1.0);
    const Point2 p{a[0] + t * ex, a[1] + t * ey};
    const double dx = q[0] - p[0], dy = q[1] - p[1], d2 = dx * dx + dy * dy;
    if (d2 < best_d2) {
      best_d2 = d2;
      best.point = p;
      const double d = std::sqrt(d2), len = std::sqrt(len2);
      best.normal = d > 1e-9 * len ? Point2{dx / d, dy / d} : Point2{-ey / len, ex / len};
    }
  }
  return best;
}

// The closed ring with every edge longer than `step` cut into equal pieces no longer than it:
// the refinement pairs points with the outline, so a stroke of a few clicked corners (whose
// pairs would leave the similarity undetermined) counts as its outline; a hand-drawn stroke of
// short edges keeps its points as drawn.
Ring densified(const Ring& ring, double step) {
  Ring out;
  for (size_t i = 0; i < ring.size(); ++i) {
    const Point2& a = ring[i];
    const Point2& b = ring[(i + 1) % ring.size()];
    const int pieces = std::max(1, int(std::ceil(std::hypot(b[0] - a[0], b[1] - a[1]) / step)));
    for (int k = 0; k < pieces; ++k)
      out.push_back({a[0] + (b[0] - a[0]) * k / pieces, a[1] + (b[1] - a[1]) * k / pieces});
  }
  return out;
}

// Refines `start` by point-to-line ICP (Chen and Medioni 1992): each stroke point is paired with
// the nearest point of the placed base outline, and the similarity minimising the squared
// distances along the pairs' normals is solved for (linear in a, b, t), until it settles. The
// moments start it within a few degrees, inside the basin of the outline's own alignment.
Similarity refine_on_outline(const Ring& stroke, const Ring& base, Similarity start, double size) {
  Similarity fit = start;
  for (int iteration = 0; iteration < 50; ++iteration) {
    const double scale2 = fit.a * fit.a + fit.b * fit.b;
    Eigen::Matrix4d normal_matrix = Eigen::Matrix4d::Zero();
    Eigen::Vector4d rhs = Eigen::Vector4d::Zero();
    for (const Point2& q : stroke) {
      // Nearest in the model's frame: a similarity keeps which point is nearest.
      const double qx = q[0] - fit.t[0], qy = q[1] - fit.t[1];
      const Point2 local{(fit.a * qx + fit.b * qy) / scale2, (-fit.b * qx + fit.a * qy) / scale2};
      const Nearest near = nearest_on_outline(base, local);
      const double s = std::sqrt(scale2);
      const Point2 n{(fit.a * near.normal[0] - fit.b * near.normal[1]) / s,
                     (fit.b * near.normal[0] + fit.a * near.normal[1]) / s};
      const Point2& p = near.point;
      const Eigen::Vector4d row{n[0] * p[0] + n[1] * p[1], -n[0] * p[1] + n[1] * p[0], n[0], n[1]};
      normal_matrix += row * row.transpose();
      rhs += row * (n[0] * q[0] + n[1] * q[1]);
    }
    const Eigen::Vector4d x = normal_matrix.ldlt().solve(rhs);
    if (!x.allFinite()) break;
    const Similarity next{x[0], x[1], {x[2], x[3]}};
    // How far the update moves the outline, at the footprint's size.
    const double moved = std::hypot(next.a - fit.a, next.b - fit.b) * size +
                         std::hypot(next.t[0] - fit.t[0], next.t[1] - fit.t[1]);
    fit = next;
    if (moved < 1e-9 * size * std::sqrt(scale2)) break;
  }
  return fit;
}

// `angle` brought into (-pi, pi].
double wrap_angle(double angle) {
  const double turn = 2 * std::numbers::pi;
  double wrapped = std::remainder(angle, turn);
  if (wrapped <= -std::numbers::pi) wrapped += turn;
  return wrapped;
}

}  // namespace

AreaAxes area_axes(const Ring& input, const std::string& where) {
  const Ring ring = open_ring(input);
  if (ring.size() < 3) {
    throw Error(where + ": a ring needs at least three distinct points, it has " +
                std::to_string(ring.size()));
  }
  for (size_t i = 0; i < ring.size(); ++i) {
    if (!std::isfinite(ring[i][0]) || !std::isfinite(ring[i][1])) {
      throw Error(where + ": point " + std::to_string(i) + " has a non-finite coordinate");
    }
  }
  // Moments about the first point, then about the centroid: no cancellation far from the origin.
  const Integrals first = integrals(ring, ring[0]);
  double extent = 0;
  for (const Point2& p : ring) {
    extent = std::max({extent, std::abs(p[0] - ring[0][0]), std::abs(p[1] - ring[0][1])});
  }
  if (!(std::abs(first.area) > 1e-12 * extent * extent)) {
    throw Error(where + ": the ring has no area (its points are collinear or repeated)");
  }
  AreaAxes axes;
  axes.centroid = {ring[0][0] + first.x / first.area, ring[0][1] + first.y / first.area};
  const Integrals central = integrals(ring, axes.centroid);
  axes.area = std::abs(central.area);
  const double vxx = central.xx / central.area, vyy = central.yy / central.area;
  const double vxy = central.xy / central.area;
  const double mean = (vxx + vyy) / 2;
  const double spread = std::hypot((vxx - vyy) / 2, vxy);
  axes.major_var = mean + spread;
  axes.minor_var = mean - spread;
  axes.angle = std::atan2(2 * vxy, vxx - vyy) / 2;
  if (axes.angle <= -std::numbers::pi / 2) axes.angle += std::numbers::pi;
  const double c = std::cos(axes.angle), s = std::sin(axes.angle);
  const double signed_area = central.area;
  axes.skew_major =
      third_moment(ring, axes.centroid, c, s) / signed_area / std::pow(axes.major_var, 1.5);
  axes.skew_minor =
      third_moment(ring, axes.centroid, -s, c) / signed_area / std::pow(axes.minor_var, 1.5);
  return axes;
}

PlaceFit fit_place(const Ring& stroke, const Ring& base, const PlaceOptions& options,
                   const std::string& feature) {
  const AreaAxes to = area_axes(stroke, feature + ": stroke");
  const AreaAxes from = area_axes(base, feature + ": base footprint");
  PlaceFit fit;
  fit.axis_ratio = to.major_var / to.minor_var;
  fit.scale = std::sqrt(to.area / from.area);
  if (options.rotation) {
    fit.rotation = wrap_angle(*options.rotation);
  } else {
    const auto check = [&](const AreaAxes& axes, const std::string& what) {
      const double ratio = axes.major_var / axes.minor_var;
      if (!(ratio >= options.min_axis_ratio)) {
        std::ostringstream message;
        message << std::setprecision(3) << feature << ": the " << what
                << "'s principal axes are nearly equal (variance ratio " << ratio << " < "
                << options.min_axis_ratio
                << "): its heading is ambiguous; give the heading explicitly";
        throw Error(message.str());
      }
    };
    check(to, "stroke");
    check(from, "base footprint");
    // The right-handed axis frames map onto each other by the rotation below or that plus a half
    // turn, which negates both skewness components: the sign of their dot product decides.
    const double agreement = from.skew_major * to.skew_major + from.skew_minor * to.skew_minor;
    fit.half_turn_decided = std::abs(agreement) >= options.min_skew_product;
    double rotation = to.angle - from.angle;
    if (fit.half_turn_decided && agreement < 0) rotation += std::numbers::pi;
    if (!fit.half_turn_decided) rotation = std::remainder(rotation, std::numbers::pi);
    fit.rotation = wrap_angle(rotation);
  }
  const double c = std::cos(fit.rotation), s = std::sin(fit.rotation);
  const Point2& b = from.centroid;
  fit.offset = {to.centroid[0] - fit.scale * (c * b[0] - s * b[1]),
                to.centroid[1] - fit.scale * (s * b[0] + c * b[1])};
  if (options.rotation || !options.refine) return fit;
  const Similarity start{fit.scale * c, fit.scale * s, fit.offset};
  const Similarity refined =
      refine_on_outline(densified(open_ring(stroke), std::sqrt(to.major_var) / kRefineDensity),
                        open_ring(base), start, std::sqrt(from.major_var));
  // A refinement that leaves the moments' fit far behind has not found the outline (a stroke
  // that does not trace it): the moments' fit stands.
  const double scale_change = std::hypot(refined.a, refined.b) / fit.scale;
  const double shift = std::hypot(refined.t[0] - fit.offset[0], refined.t[1] - fit.offset[1]);
  if (!(scale_change > 0.8 && scale_change < 1.25 && shift < std::sqrt(to.major_var))) {
    fit.outline_not_found = true;
    return fit;
  }
  fit.rotation = std::atan2(refined.b, refined.a);
  fit.scale = std::hypot(refined.a, refined.b);
  fit.offset = refined.t;
  return fit;
}

TangentPlaneRing tangent_plane_ring(const std::vector<LonLat>& ring, const std::string& where) {
  if (ring.empty()) throw Error(where + ": the stroke has no points");
  std::vector<LonLat> unwrapped;
  double lon_sum = 0, lat_sum = 0;
  for (size_t i = 0; i < ring.size(); ++i) {
    const LonLat& p = ring[i];
    if (!std::isfinite(p.lon) || !std::isfinite(p.lat) || std::abs(p.lat) > 90) {
      std::ostringstream message;
      message << std::setprecision(10) << where << ": point " << i << " (lon " << p.lon << ", lat "
              << p.lat << ") is not on the globe";
      throw Error(message.str());
    }
    const double lon = ring[0].lon + std::remainder(p.lon - ring[0].lon, 360.0);
    unwrapped.push_back({lon, p.lat});
    lon_sum += lon;
    lat_sum += p.lat;
  }
  const double count = static_cast<double>(ring.size());
  TangentPlaneRing plane;
  plane.origin = {std::remainder(lon_sum / count, 360.0), lat_sum / count, 0};
  const EnuFrame frame = enu_frame(plane.origin);
  for (const LonLat& p : unwrapped) {
    const auto [x, y, z] = frame.to_enu(p.lon, p.lat);
    plane.ring.push_back({x, y});
  }
  return plane;
}

double rotation_from_heading_deg(double heading_deg) {
  return wrap_angle(-heading_deg * std::numbers::pi / 180);
}

}  // namespace maquette::structures
