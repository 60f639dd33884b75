#include "building_mesh.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "building_solid.h"
#include "content/enu_transform.h"
#include "core/enu_frame.h"
#include "footprint.h"
#include "roof_planes.h"
#include "roof_surface.h"
#include "terrain_base.h"

namespace maquette::structures {
namespace {

const std::vector<GeoPolygon>& polygons_of(const VectorFeature& f) {
  if (f.geometry.type != GeometryType::Polygon && f.geometry.type != GeometryType::MultiPolygon)
    throw InvalidFootprint("its geometry is a " + std::string(geometry_type_name(f.geometry.type)) +
                           ", not a Polygon or MultiPolygon");
  if (f.geometry.polygons.empty() || f.geometry.polygons.front().rings.empty() ||
      f.geometry.polygons.front().rings.front().empty())
    throw InvalidFootprint("its geometry is empty");
  return f.geometry.polygons;
}

struct BuiltRoof {
  Solid solid;
  double top = 0;  // the roof's top above the base (m)
  RoofShape shape = RoofShape::Flat;
};

// A part's solid under its roof, checked; a pitched roof that gives no valid solid (its creases
// grazing the footprint) is built flat at its top instead, with a warning.
BuiltRoof roof_of(const Footprint& part, const BuildingTags& tags, std::string* warning) {
  const RoofFrame frame = roof_frame(part, tags);
  const PartHeights heights = part_heights(tags, roof_run(frame, tags.roof));
  std::string problem;
  try {
    const RoofSurface roof = roof_surface(part, roof_planes(frame, tags.roof, heights));
    BuiltRoof built{extrude(roof), heights.top(), tags.roof};
    problem = solid_problem(built.solid, roof.volume());
    if (problem.empty()) return built;
  } catch (const InvalidFootprint& e) {
    problem = e.what();
  }
  if (tags.roof == RoofShape::Flat) throw InvalidFootprint("its solid is invalid: " + problem);
  if (warning)
    *warning = std::string("its ") + roof_shape_name(tags.roof) + " roof gives no valid solid (" +
               problem + "): built flat";
  BuiltRoof flat{extrude(part, heights.top()), heights.top()};
  if (problem = solid_problem(flat.solid, part.area * flat.top); !problem.empty())
    throw InvalidFootprint("its solid is invalid: " + problem);
  return flat;
}

}  // namespace

MeshObject building_mesh(const VectorFeature& feature, const HeightRules& rules,
                         const BuildingSite& site, std::string* warning) {
  const std::vector<GeoPolygon>& polygons = polygons_of(feature);
  const BuildingTags tags = building_tags(feature.attributes, rules);
  if (warning) *warning = tags.warning;
  const int tile_size = site.dem->size();
  const PixelFrame pixel(*site.grid, site.cell, tile_size);

  std::vector<PixelRing> pixel_rings;
  for (const GeoPolygon& polygon : polygons)
    for (const GeoPath& ring : polygon.rings) {
      PixelRing& r = pixel_rings.emplace_back();
      for (const GeoPoint& p : ring) {
        // Another face's points are placed in that face's plane, where the halo's pixels (turned
        // across the edge) need not follow.
        if (site.grid->cell_from_point({p.lon, p.lat}, 0).face() != site.cell.face())
          throw InvalidFootprint("it crosses an edge of the grid's faces: not handled yet");
        r.push_back(pixel(*site.grid, {p.lon, p.lat}));
      }
    }
  const std::optional<float> base = lowest_terrain(*site.dem, pixel_rings);
  if (!base) throw InvalidFootprint("the DEM has no data under the footprint");

  const GeoPoint& anchor = polygons.front().rings.front().front();
  const double base_above_ellipsoid =
      site.to_ellipsoid ? (*site.to_ellipsoid)({anchor.lon, anchor.lat}, *base) : *base;
  const EnuFrame building({anchor.lon, anchor.lat, base_above_ellipsoid});
  const EnuFrame content = enu_frame(site.origin);
  std::vector<Footprint> parts;
  for (const GeoPolygon& polygon : polygons) {
    std::vector<PlaneRing> rings;
    for (const GeoPath& ring : polygon.rings) {
      PlaneRing& r = rings.emplace_back();
      for (const GeoPoint& p : ring) {
        const auto [x, y, z] = building.to_enu(p.lon, p.lat, base_above_ellipsoid);
        r.push_back({x, y});
      }
    }
    parts.push_back(make_footprint(std::move(rings)));
  }
  if (parts.size() > 1) check_disjoint(parts);

  MeshObject object;
  double area = 0, height = 0;
  RoofShape shape = tags.roof;
  for (const Footprint& part : parts) {
    const BuiltRoof built = roof_of(part, tags, warning);
    const Solid& solid = built.solid;
    height = std::max(height, built.top);
    if (built.shape != tags.roof) shape = built.shape;
    area += part.area;
    const uint32_t first = uint32_t(object.positions.size() / 3);
    for (size_t v = 0; v < solid.positions.size(); v += 3) {
      const auto [lon, lat, h] =
          building.to_geodetic(solid.positions[v], solid.positions[v + 1], solid.positions[v + 2]);
      const auto [x, y, z] = content.to_enu(lon, lat, h);
      object.positions.insert(object.positions.end(), {float(x), float(y), float(z)});
      if (site.texture) {
        // From the DEM's pixels to the image's, both spanning the cell.
        const PlanePoint2 p = pixel(*site.grid, {lon, lat});
        const double scale = double(site.texture->size) / tile_size;
        const double width = site.texture->size + 2.0 * site.texture->halo;
        object.uvs.insert(object.uvs.end(), {float((p[0] * scale + site.texture->halo) / width),
                                             float((p[1] * scale + site.texture->halo) / width)});
      }
    }
    for (const uint32_t i : solid.indices) object.indices.push_back(first + i);
  }
  object.provenance = {uint64_t(feature.id),
                       feature.id,
                       "structures.buildings",
                       {{"height_m", height},
                        {"base_m", *base},
                        {"area_m2", area},
                        {"roof_shape", roof_shape_name(shape)}}};
  return object;
}

}  // namespace maquette::structures
