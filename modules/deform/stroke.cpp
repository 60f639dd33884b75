#include "stroke.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "core/error.h"

namespace maquette::deform {
namespace {

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
    if (!a.contains("cross_section"))
      throw Error(where + ": no cross_section attribute ([[offset_m, dz_m]...])");
    s.cross_section = parse_knots(a["cross_section"], where + ": cross_section");
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
