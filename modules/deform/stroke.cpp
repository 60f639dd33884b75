#include "stroke.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "core/enu_frame.h"
#include "core/error.h"

namespace maquette::deform {
namespace {

using Point2 = std::array<double, 2>;

double cross(Point2 a, Point2 b) { return a[0] * b[1] - a[1] * b[0]; }
double dot(Point2 a, Point2 b) { return a[0] * b[0] + a[1] * b[1]; }
Point2 minus(Point2 a, Point2 b) { return {a[0] - b[0], a[1] - b[1]}; }

double point_segment_distance(Point2 p, Point2 a, Point2 b) {
  const Point2 ab = minus(b, a), ap = minus(p, a);
  const double t = std::clamp(dot(ap, ab) / dot(ab, ab), 0.0, 1.0);
  return std::hypot(ap[0] - t * ab[0], ap[1] - t * ab[1]);
}

// Distance between segments ab and cd (non-degenerate): 0 when they cross.
double segment_distance(Point2 a, Point2 b, Point2 c, Point2 d) {
  const double d1 = cross(minus(b, a), minus(c, a)), d2 = cross(minus(b, a), minus(d, a));
  const double d3 = cross(minus(d, c), minus(a, c)), d4 = cross(minus(d, c), minus(b, c));
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
    return 0;
  return std::min({point_segment_distance(a, c, d), point_segment_distance(b, c, d),
                   point_segment_distance(c, a, b), point_segment_distance(d, a, b)});
}

// The pairs (i, j), i < j, of segments whose bounding boxes grown by kSelfContactM overlap, and
// every consecutive pair (j = i + 1), sorted: a sweep along the axis of the curve's larger extent
// (segments by their box's start there, each compared with the earlier ones whose box has not
// ended), so that a long curve costs about its length, not its square.
std::vector<std::array<size_t, 2>> candidate_pairs(const std::vector<Point2>& at,
                                                   const std::vector<size_t>& segments) {
  const size_t n = segments.size();
  std::vector<std::array<Point2, 2>> box(n);  // per segment: low and high corner, grown
  Point2 low{INFINITY, INFINITY}, high{-INFINITY, -INFINITY};
  for (size_t i = 0; i < n; ++i) {
    const Point2 a = at[segments[i]], b = at[segments[i] + 1];
    box[i] = {Point2{std::min(a[0], b[0]) - kSelfContactM, std::min(a[1], b[1]) - kSelfContactM},
              Point2{std::max(a[0], b[0]) + kSelfContactM, std::max(a[1], b[1]) + kSelfContactM}};
    for (size_t k = 0; k < 2; ++k)
      low[k] = std::min(low[k], box[i][0][k]), high[k] = std::max(high[k], box[i][1][k]);
  }
  const size_t axis = high[0] - low[0] >= high[1] - low[1] ? 0 : 1, other = 1 - axis;
  std::vector<size_t> order(n);
  for (size_t i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](size_t i, size_t j) {
    return box[i][0][axis] < box[j][0][axis] || (box[i][0][axis] == box[j][0][axis] && i < j);
  });
  std::vector<std::array<size_t, 2>> pairs;
  for (size_t i = 0; i + 1 < n; ++i) pairs.push_back({i, i + 1});
  std::vector<size_t> open;  // segments whose box may still overlap the next ones along the axis
  for (const size_t j : order) {
    std::erase_if(open, [&](size_t i) { return box[i][1][axis] < box[j][0][axis]; });
    for (const size_t i : open)
      if (std::max(i, j) - std::min(i, j) > 1 && box[i][0][other] <= box[j][1][other] &&
          box[j][0][other] <= box[i][1][other])
        pairs.push_back({std::min(i, j), std::max(i, j)});
    open.push_back(j);
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

// Throws when the control curve comes within kSelfContactM of itself: two segments that are not
// consecutive meet (cross, touch, or overlap collinearly), or a segment turns back over the one
// before (more than a right angle, the shorter one's far end on the other). Segments are numbered
// from 1 as in the LineString; zero-length ones are skipped. In metres, on the tangent plane of
// the curve's first point. The fault named is the first pair (i, j) in order of i then j, as if
// every pair were tried; only those whose grown boxes overlap are (candidate_pairs).
void check_self_contact(const std::vector<LonLat>& curve, const std::string& where) {
  const EnuFrame plane({curve.front().lon, curve.front().lat, 0});
  std::vector<Point2> at;
  for (const LonLat& p : curve) {
    const auto [x, y, z] = plane.to_enu(p.lon, p.lat);
    at.push_back({x, y});
  }
  std::vector<size_t> segments;  // index of each non-degenerate segment's first point
  for (size_t i = 0; i + 1 < at.size(); ++i)
    if (at[i] != at[i + 1]) segments.push_back(i);
  const auto fault = [&](size_t i, size_t j, const char* what) {
    return Error(where + ": the control curve " + what + " (segments " +
                 std::to_string(segments[i] + 1) + " and " + std::to_string(segments[j] + 1) + ")");
  };
  for (const auto& [i, j] : candidate_pairs(at, segments)) {
    const Point2 a = at[segments[i]], b = at[segments[i] + 1];
    const Point2 c = at[segments[j]], d = at[segments[j] + 1];
    if (j == i + 1) {  // consecutive (zero-length ones between skipped): they share b == c
      const bool turns_back = dot(minus(b, a), minus(d, c)) < 0;
      if (turns_back && std::min(point_segment_distance(d, a, b),
                                 point_segment_distance(a, c, d)) <= kSelfContactM)
        throw fault(i, j, "turns back over itself");
    } else if (segment_distance(a, b, c, d) <= kSelfContactM) {
      throw fault(i, j, "crosses itself");
    }
  }
}

Knots parse_knots(const nlohmann::json& value, const std::string& where) {
  if (!value.is_array() || value.size() < 2)
    throw Error(where + ": expected an array of at least two [number, number] pairs, got " +
                value.dump().substr(0, 80));
  Knots knots;
  for (size_t i = 0; i < value.size(); ++i) {
    const nlohmann::json& pair = value[i];
    const std::string at = where + "[" + std::to_string(i) + "]";
    if (!pair.is_array() || pair.size() != 2 || !pair[0].is_number() || !pair[1].is_number())
      throw Error(at + ": expected [number, number], got " + pair.dump().substr(0, 80));
    const std::array<double, 2> knot{pair[0].get<double>(), pair[1].get<double>()};
    if (!std::isfinite(knot[0]) || !std::isfinite(knot[1]))
      throw Error(at + ": the values must be finite, got " + pair.dump());
    if (!knots.empty() && knot[0] <= knots.back()[0])
      throw Error(at + ": its first value " + pair[0].dump() +
                  " does not increase on the previous pair's");
    knots.push_back(knot);
  }
  return knots;
}

}  // namespace

std::string lonlat_text(LonLat p) {
  std::ostringstream s;
  s.precision(8);
  s << "lon " << p.lon << ", lat " << p.lat;
  return s.str();
}

double piecewise_linear(const Knots& knots, double x) {
  if (x <= knots.front()[0]) return knots.front()[1];
  if (x >= knots.back()[0]) return knots.back()[1];
  const auto after =
      std::upper_bound(knots.begin(), knots.end(), x,
                       [](double v, const std::array<double, 2>& k) { return v < k[0]; });
  const auto before = after - 1;
  const double t = (x - (*before)[0]) / ((*after)[0] - (*before)[0]);
  return (*before)[1] + t * ((*after)[1] - (*before)[1]);
}

std::vector<FeatureStroke> feature_strokes(const FeatureList& features, const std::string& port) {
  std::vector<FeatureStroke> strokes;
  for (const VectorFeature* f : features) {
    const nlohmann::json& a = f->attributes;
    const auto tool = a.find("tool");
    if (tool == a.end() || !tool->is_string() || tool->get<std::string>() != "feature") continue;
    const std::string where = "inputs." + port + ": feature " + std::to_string(f->id);
    if (f->geometry.type != GeometryType::LineString || f->geometry.lines.size() != 1)
      throw Error(where + ": a stroke of tool 'feature' is a LineString (the control curve)");
    FeatureStroke s;
    s.id = f->id;
    for (const GeoPoint& p : f->geometry.lines.front()) {
      s.curve.push_back({p.lon, p.lat});
      if (f->geometry.has_z) s.z.push_back(p.z);
    }
    const bool distinct = std::any_of(s.curve.begin(), s.curve.end(), [&](const LonLat& p) {
      return p.lon != s.curve.front().lon || p.lat != s.curve.front().lat;
    });
    if (s.curve.size() < 2 || !distinct)
      throw Error(where + ": the control curve needs at least two distinct points");
    if (std::any_of(s.z.begin(), s.z.end(), [](double z) { return !std::isfinite(z); }))
      throw Error(where + ": a Z value of the control curve is not finite");
    check_self_contact(s.curve, where);
    if (!a.contains("cross_section"))
      throw Error(where + ": no cross_section attribute ([[offset_m, dz_m]...])");
    s.cross_section = parse_knots(a["cross_section"], where + ": cross_section");
    const double dz0 = piecewise_linear(s.cross_section, 0);
    if (s.cross_section.front()[0] <= 0 && s.cross_section.back()[0] >= 0 &&
        std::abs(dz0) > kCurveDzToleranceM)
      throw Error(where + ": cross_section: dz at offset 0 is " + nlohmann::json(dz0).dump() +
                  " m, but the control curve's elevation holds there: make it 0 (and move the "
                  "curve, its Z or its profile, to where the section meets it)");
    if (a.contains("profile") && !a["profile"].is_null()) {
      if (!s.z.empty())
        throw Error(where + ": both Z values and a profile give the curve's elevation; keep one");
      s.profile = parse_knots(a["profile"], where + ": profile");
      if (s.profile.front()[0] < 0)
        throw Error(where + ": profile: distances start at 0, got " +
                    std::to_string(s.profile.front()[0]));
    }
    strokes.push_back(std::move(s));
  }
  return strokes;
}

}  // namespace maquette::deform
