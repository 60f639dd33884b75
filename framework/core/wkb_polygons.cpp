#include "core/wkb_polygons.h"

#include "core/error.h"
#include "core/geometry.h"

namespace maquette {

std::vector<PolygonRings> wkb_polygons(std::span<const std::byte> wkb, const std::string& where) {
  const Geometry g = parse_wkb(wkb, where);
  if (g.type != GeometryType::Polygon && g.type != GeometryType::MultiPolygon)
    throw Error(where + " is a " + std::string(geometry_type_name(g.type)) + ", not a polygon");
  std::vector<PolygonRings> out;
  for (const GeoPolygon& polygon : g.polygons) {
    PolygonRings& rings = out.emplace_back();
    for (const GeoPath& ring : polygon.rings) {
      auto& r = rings.emplace_back();
      for (const GeoPoint& p : ring) r.push_back({p.lon, p.lat});
    }
  }
  return out;
}

}  // namespace maquette
