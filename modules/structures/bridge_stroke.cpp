#include "bridge_stroke.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.h"

namespace maquette::structures {
namespace {

// A distance in degrees of latitude between two nearby points, enough to tell near from far.
double degrees_apart(const GeoPoint& a, const GeoPoint& b) {
  const double cos_lat = std::cos((a.lat + b.lat) / 2 * std::numbers::pi / 180);
  return std::hypot((a.lon - b.lon) * cos_lat, a.lat - b.lat);
}

}  // namespace

bool is_bridge_stroke(const VectorFeature& f) {
  const auto tool = f.attributes.find("tool");
  return tool != f.attributes.end() && *tool == "bridge";
}

BridgeStroke bridge_stroke(const VectorFeature& f, double default_thickness_m) {
  const std::string where = "feature " + std::to_string(f.id) + " (tool bridge)";
  const Geometry& g = f.geometry;
  if (g.type != GeometryType::MultiLineString || g.lines.size() != 2)
    throw Error(where + ": geometry: a " + std::string(geometry_type_name(g.type)) + " of " +
                std::to_string(g.type == GeometryType::MultiLineString ? g.lines.size() : 1) +
                " part(s), not a MultiLineString of the deck's two edges");
  for (size_t k = 0; k < 2; ++k) {
    const std::vector<GeoPoint>& edge = g.lines[k];
    const bool distinct = std::any_of(edge.begin(), edge.end(), [&](const GeoPoint& p) {
      return p.lon != edge.front().lon || p.lat != edge.front().lat;
    });
    if (edge.size() < 2 || !distinct)
      throw Error(where + ": geometry: edge " + std::to_string(k + 1) + " has " +
                  std::to_string(edge.size()) +
                  " point(s) and fewer than 2 distinct ones: an edge needs 2");
  }
  BridgeStroke b{f.id, g.lines[0], g.lines[1], default_thickness_m};
  if (degrees_apart(b.first_edge.back(), b.second_edge.front()) <
      degrees_apart(b.first_edge.front(), b.second_edge.front()))
    std::reverse(b.second_edge.begin(), b.second_edge.end());
  if (const auto t = f.attributes.find("thickness_m"); t != f.attributes.end()) {
    if (!t->is_number() || !(t->get<double>() > 0) || !(t->get<double>() <= kMaxDeckThicknessM))
      throw Error(where + ": thickness_m: " + t->dump() + " is not a positive number of metres " +
                  "up to " + std::to_string(int(kMaxDeckThicknessM)));
    b.thickness_m = t->get<double>();
  }
  return b;
}

}  // namespace maquette::structures
