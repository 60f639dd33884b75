#include "hs_classes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.h"
#include "hs_histogram.h"

namespace maquette::texture {
namespace {

bool in_range(double v, const std::array<double, 2>& r) { return v >= r[0] && v <= r[1]; }

bool in_hue(double h, const std::array<double, 2>& r) {
  return r[0] <= r[1] ? in_range(h, r) : (h >= r[0] || h <= r[1]);
}

using Point2 = std::array<double, 2>;

// Distance (saturation units) within which a point counts as on a polygon's edge: covers the
// rounding of cos and sin, so that a point meant to be on an edge (the grey point on an edge
// through the origin) is, and far below the saturation step of 8-bit colours (1/255).
constexpr double kOnEdge = 1e-9;

double cross(const Point2& o, const Point2& a, const Point2& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

double squared_segment_distance(const Point2& p, const Point2& a, const Point2& b) {
  const double dx = b[0] - a[0], dy = b[1] - a[1], length2 = dx * dx + dy * dy;
  const double t =
      length2 > 0 ? std::clamp(((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / length2, 0.0, 1.0) : 0;
  const double ex = p[0] - a[0] - t * dx, ey = p[1] - a[1] - t * dy;
  return ex * ex + ey * ey;
}

// The polygons parameter: [hue, saturation] points checked here (the schema checks only that
// they are arrays of numbers), turned into colour-wheel vertices.
std::vector<Polygon> parse_polygons(const nlohmann::json& list) {
  std::vector<Polygon> out;
  for (size_t i = 0; i < list.size(); ++i) {
    const std::string field = "params.polygons[" + std::to_string(i) + "].points";
    const nlohmann::json& points = list[i].at("points");
    if (points.size() < 3)
      throw Error(field + ": expected at least 3 [hue, saturation] points, got " +
                  std::to_string(points.size()));
    Polygon polygon{list[i].at("id").get<int>(), {}};
    for (size_t k = 0; k < points.size(); ++k) {
      const nlohmann::json& q = points[k];
      const std::string at = field + "[" + std::to_string(k) + "]";
      if (!q.is_array() || q.size() != 2 || !q[0].is_number() || !q[1].is_number())
        throw Error(at + ": expected [hue, saturation], got " + q.dump());
      const double hue = q[0].get<double>(), saturation = q[1].get<double>();
      if (!(hue >= 0 && hue <= 360))
        throw Error(at + ": hue " + q[0].dump() + " is outside [0, 360]");
      if (!(saturation >= 0 && saturation <= 1))
        throw Error(at + ": saturation " + q[1].dump() + " is outside [0, 1]");
      polygon.vertices.push_back(wheel(hue, saturation));
    }
    // Some triangle of the first vertex and two others has an area, else all are on one line.
    const auto& v = polygon.vertices;
    bool has_area = false;
    for (size_t a = 1; a < v.size() && !has_area; ++a)
      for (size_t b = a + 1; b < v.size() && !has_area; ++b)
        has_area = std::abs(cross(v[0], v[a], v[b])) > kOnEdge;
    if (!has_area) throw Error(field + ": the points are on one line, got " + points.dump());
    out.push_back(std::move(polygon));
  }
  return out;
}

std::array<double, 2> pair(const nlohmann::json& j, const char* key,
                           std::array<double, 2> fallback) {
  return j.contains(key) ? std::array<double, 2>{j[key][0].get<double>(), j[key][1].get<double>()}
                         : fallback;
}

}  // namespace

bool Polygon::contains(const std::array<double, 2>& p) const {
  bool inside = false;
  for (size_t i = 0, j = vertices.size() - 1; i < vertices.size(); j = i++) {
    const Point2 &a = vertices[i], &b = vertices[j];
    if (squared_segment_distance(p, a, b) <= kOnEdge * kOnEdge) return true;
    // Crossing test (edges half-open in y, so a ray through a vertex counts it once).
    if ((a[1] > p[1]) != (b[1] > p[1]) &&
        p[0] < a[0] + (b[0] - a[0]) * (p[1] - a[1]) / (b[1] - a[1]))
      inside = !inside;
  }
  return inside;
}

std::array<double, 2> wheel(double hue, double saturation) {
  const double a = hue * M_PI / 180;
  return {saturation * std::cos(a), saturation * std::sin(a)};
}

nlohmann::json grey_params_schema() {
  return {{"grey_threshold",
           {{"type", "number"},
            {"minimum", 0},
            {"maximum", 255},
            {"default", 10},
            {"description", "max(R,G,B) - min(R,G,B) at or below which a pixel is grey"}}},
          {"grey_hue",
           {{"type", "number"},
            {"minimum", 0},
            {"maximum", 360},
            {"default", 300},
            {"description", "hue given to grey pixels"}}}};
}

HsClassifier HsClassifier::from_params(const nlohmann::json& p) {
  HsClassifier c;
  c.grey_threshold = p.at("grey_threshold").get<double>();
  c.grey_hue = p.at("grey_hue").get<double>();
  for (const auto& b : p.value("boxes", nlohmann::json::array()))
    c.boxes.push_back({b.at("id").get<int>(), pair(b, "hue", {0, 360}),
                       pair(b, "saturation", {0, 1}), pair(b, "value", {0, 1})});
  c.polygons = parse_polygons(p.value("polygons", nlohmann::json::array()));
  for (const auto& z : p.value("centres", nlohmann::json::array())) {
    const int id = z.at("id").get<int>();
    if (z.contains("L") && z.contains("a") && z.contains("b") && !z.contains("hue") &&
        !z.contains("saturation") && !z.contains("value"))
      c.centres.push_back(
          {id, 0, 0, NAN, Lab{z["L"].get<double>(), z["a"].get<double>(), z["b"].get<double>()}});
    else if (z.contains("hue") && z.contains("saturation") && !z.contains("L") &&
             !z.contains("a") && !z.contains("b"))
      c.centres.push_back({id, z["hue"].get<double>(), z["saturation"].get<double>(),
                           z.value("value", double(NAN)), std::nullopt});
    else
      throw Error("params.centres: centre id " + std::to_string(id) +
                  ": give \"hue\" and \"saturation\" (and \"value\"), or \"L\", \"a\" and "
                  "\"b\", got " +
                  z.dump());
  }
  for (const Centre& z : c.centres) {
    if (z.lab.has_value() != c.centres.front().lab.has_value())
      throw Error("params.centres: give CIELAB colours for every centre or for none (centre id " +
                  std::to_string(z.id) + ")");
    if (std::isnan(z.value) != std::isnan(c.centres.front().value) && !z.lab)
      throw Error("params.centres: give \"value\" for every centre or for none (centre id " +
                  std::to_string(z.id) + ")");
  }
  return c;
}

Hsv HsClassifier::hsv(double r, double g, double b) const {
  Hsv x = rgb_to_hsv(r, g, b);
  if (std::max({r, g, b}) - std::min({r, g, b}) <= grey_threshold) x.h = grey_hue;
  return x;
}

int HsClassifier::classify(double r, double g, double b) const {
  const Hsv x = hsv(r, g, b);
  for (const Box& box : boxes)
    if (in_hue(x.h, box.hue) && in_range(x.s, box.saturation) && in_range(x.v, box.value))
      return box.id;
  const auto p = wheel(x.h, x.s);
  for (const Polygon& polygon : polygons)
    if (polygon.contains(p)) return polygon.id;
  int best = -1;
  double best_d = std::numeric_limits<double>::infinity();
  if (!centres.empty() && centres.front().lab) {
    const Point here = lab_point(srgb_to_lab(r, g, b));
    for (const Centre& z : centres)
      if (const double d = squared_distance(here, lab_point(*z.lab)); d < best_d)
        best_d = d, best = z.id;
    return best;
  }
  for (const Centre& z : centres) {
    const auto q = wheel(z.hue, z.saturation);
    const double dv = std::isnan(z.value) ? 0 : x.v - z.value;
    const double d = std::hypot(p[0] - q[0], p[1] - q[1], dv);
    if (d < best_d) best_d = d, best = z.id;
  }
  return best;
}

}  // namespace maquette::texture
