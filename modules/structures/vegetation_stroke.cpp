#include "vegetation_stroke.h"

#include <cmath>

#include "core/error.h"

namespace maquette::structures {
namespace {

std::vector<PolygonRings> as_rings(const std::vector<std::vector<PlaneRing>>& polygons) {
  std::vector<PolygonRings> out;
  for (const auto& polygon : polygons) {
    PolygonRings rings;
    for (const PlaneRing& ring : polygon) {
      rings.emplace_back();
      for (const PlanePoint2& p : ring) rings.back().push_back({p[0], p[1]});
    }
    out.push_back(std::move(rings));
  }
  return out;
}

double spacing_of(const VectorFeature& f, const std::string& where) {
  const auto it = f.attributes.find("spacing_m");
  if (it == f.attributes.end() || it->is_null()) return 0;  // to be estimated
  if (!it->is_number() || !(it->get<double>() > 0) || !std::isfinite(it->get<double>()))
    throw Error(where + ": field 'spacing_m' is " + it->dump() + ", not a positive number");
  return it->get<double>();
}

}  // namespace

PlanePoint VegetationStroke::to_plane(LonLat p) const {
  const auto [x, y, z] = plane.to_enu(p.lon, p.lat);
  return {x, y};
}

LonLat VegetationStroke::to_ground(PlanePoint p) const {
  const GeodeticPoint g = plane.to_geodetic(p.x, p.y, 0);
  return {g.lon, g.lat};
}

InputSpec strokes_input() {
  InputSpec strokes;
  strokes.name = "strokes";
  strokes.description = "features layer: (Multi)Polygon strokes with tool 'vegetation'";
  strokes.kind = LayerKind::Features;
  return strokes;
}

std::vector<VegetationStroke> vegetation_strokes(const FeatureList& features,
                                                 const std::string& port) {
  std::vector<VegetationStroke> out;
  for (const VectorFeature* f : features) {
    const auto tool = f->attributes.find("tool");
    if (tool == f->attributes.end() || !tool->is_string() ||
        tool->get_ref<const std::string&>() != "vegetation")
      continue;
    const std::string where =
        "inputs." + port + ": feature " + std::to_string(f->id) + " (tool vegetation)";
    if (f->geometry.type != GeometryType::Polygon && f->geometry.type != GeometryType::MultiPolygon)
      throw Error(where + ": a " + std::string(geometry_type_name(f->geometry.type)) +
                  ", not a closed stroke (Polygon or MultiPolygon)");
    if (f->geometry.polygons.empty() || f->geometry.polygons.front().rings.empty() ||
        f->geometry.polygons.front().rings.front().size() < 4)
      throw Error(where + ": an empty polygon, not a closed stroke");
    const GeoPoint& first = f->geometry.polygons.front().rings.front().front();
    VegetationStroke s{
        f, spacing_of(*f, where), EnuFrame({first.lon, first.lat, 0}), {}, PolygonSet({})};
    for (const GeoPolygon& polygon : f->geometry.polygons) {
      s.polygons.emplace_back();
      for (const GeoPath& ring : polygon.rings) {
        s.polygons.back().emplace_back();
        for (const GeoPoint& p : ring) {
          const PlanePoint q = s.to_plane({p.lon, p.lat});
          s.polygons.back().back().push_back({q.x, q.y});
        }
      }
    }
    s.region = PolygonSet(as_rings(s.polygons));
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace maquette::structures
