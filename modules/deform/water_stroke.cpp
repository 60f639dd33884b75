#include "water_stroke.h"

#include "core/error.h"
#include "stroke.h"

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
    throw Error(describe(f) + " is a " + std::string(geometry_type_name(f.geometry.type)) +
                ", not a Polygon around a basin");
  PolygonRings rings;
  for (const GeoPath& ring : f.geometry.polygons.front().rings) {
    rings.emplace_back();
    for (const GeoPoint& p : ring) rings.back().push_back({p.lon, p.lat});
  }
  return PolygonSet({rings});
}

void claim_pixel(std::vector<const VectorFeature*>& owner, size_t i, const VectorFeature& f,
                 LonLat centre) {
  if (owner[i] && owner[i] != &f)
    throw Error(describe(*owner[i]) + " and " + describe(f) + " overlap at " + lonlat_text(centre) +
                ": water strokes must not overlap (draw one stroke around both basins, or keep "
                "them apart)");
  owner[i] = &f;
}

}  // namespace maquette::deform
