#include "water_stroke.h"

#include <stdexcept>

namespace maquette::deform {

bool is_water_stroke(const VectorFeature& f) {
  const auto tool = f.attributes.find("tool");
  return tool != f.attributes.end() && *tool == "water";
}

std::string describe(const VectorFeature& f) {
  return "feature " + std::to_string(f.id) + " (tool water)";
}

PolygonSet stroke_polygon(const VectorFeature& f) {
  if (f.geometry.type != GeometryType::Polygon)
    throw std::runtime_error(describe(f) + " is a " +
                             std::string(geometry_type_name(f.geometry.type)) +
                             ", not a Polygon around a basin");
  PolygonRings rings;
  for (const GeoPath& ring : f.geometry.polygons.front().rings) {
    rings.emplace_back();
    for (const GeoPoint& p : ring) rings.back().push_back({p.lon, p.lat});
  }
  return PolygonSet({rings});
}

}  // namespace maquette::deform
