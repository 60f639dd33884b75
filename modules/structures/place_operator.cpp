#include <cmath>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "building_mesh.h"
#include "content/enu_transform.h"
#include "core/enu_frame.h"
#include "core/error.h"
#include "gdal/vertical_datum.h"
#include "gltf/prototype_library.h"
#include "model_base.h"
#include "operators.h"
#include "place_stroke.h"
#include "terrain_base.h"

namespace maquette::structures {
namespace {

OperatorSpec place_spec() {
  OperatorSpec s;
  s.name = "structures.place";
  s.description =
      "Models placed by transformation strokes (paper 002 §7.4): a closed stroke around a "
      "footprint gives a model layer's rotation about the vertical, uniform scale and position; "
      "the terrain its base height";
  s.kind = OperatorKind::Cell;
  s.halo = kDemHaloPixels;  // the terrain under a model's base reaching beyond the cell
  s.inputs.push_back(single_channel_input(
      "dem", "terrain heights (m above the layer's vertical datum)", Semantics::Continuous));
  InputSpec strokes;
  strokes.name = "strokes";
  strokes.description =
      "features layer: closed strokes (Polygons or closed LineStrings) of tool 'place', "
      "properties `model` (a model layer or builtin:* prototype; or `object`) and optional "
      "`heading_deg` (or `heading`)";
  strokes.kind = LayerKind::Features;
  s.inputs.push_back(strokes);
  OutputSpec instances;
  instances.name = "instances";
  instances.description = "one instance of its model per stroke, in the cell of its position";
  instances.kind = LayerKind::Instances;
  s.outputs.push_back(instances);
  s.params_schema = {{"type", "object"}, {"additionalProperties", false}};
  return s;
}

bool is_place_stroke(const VectorFeature& f) {
  const auto tool = f.attributes.find("tool");
  return tool != f.attributes.end() && *tool == "place";
}

// What a stroke of tool 'place' asks for.
struct PlaceStroke {
  std::string model;
  std::optional<double> heading_deg;
  std::vector<LonLat> ring;  // the outer ring
};

// A property of the stroke and the name it was found under (for messages).
struct NamedProperty {
  const json* value = nullptr;  // nullptr when absent
  std::string name;
};

// The property `name` of the stroke, or its `alias`. Throws maquette::Error when both are, with
// different values.
NamedProperty property(const VectorFeature& f, const std::string& where, const char* name,
                       const char* alias) {
  const auto a = f.attributes.find(name), b = f.attributes.find(alias);
  if (a != f.attributes.end() && b != f.attributes.end() && *a != *b)
    throw Error(where + ": properties '" + name + "' (" + a->dump() + ") and '" + alias + "' (" +
                b->dump() + ") disagree: give one");
  if (a != f.attributes.end()) return {&*a, name};
  if (b != f.attributes.end()) return {&*b, alias};
  return {nullptr, name};
}

PlaceStroke place_stroke(const VectorFeature& f, const std::string& where) {
  PlaceStroke s;
  const Geometry& g = f.geometry;
  const GeoPath* ring = nullptr;
  if (g.type == GeometryType::Polygon && g.polygons.size() == 1 && !g.polygons[0].rings.empty())
    ring = &g.polygons[0].rings[0];
  if (g.type == GeometryType::LineString && g.lines.size() == 1 && g.lines[0].size() >= 4 &&
      g.lines[0].front().lon == g.lines[0].back().lon &&
      g.lines[0].front().lat == g.lines[0].back().lat)
    ring = &g.lines[0];
  if (!ring)
    throw Error(where + ": a stroke of tool 'place' is closed (a Polygon, or a LineString ending " +
                "where it begins), not this " + std::string(geometry_type_name(g.type)));
  for (const GeoPoint& p : *ring) s.ring.push_back({p.lon, p.lat});
  // DESIGN.md's stroke convention names them `object` and `heading`: either name is taken.
  const auto [model, model_name] = property(f, where, "model", "object");
  if (!model || !model->is_string() || model->get<std::string>().empty())
    throw Error(where + ": property '" + model_name + "' (the name of a model layer) is " +
                (!model ? "missing" : "not a name: " + model->dump()));
  s.model = model->get<std::string>();
  if (const auto [heading, heading_name] = property(f, where, "heading_deg", "heading");
      heading && !heading->is_null()) {
    if (!heading->is_number() || !std::isfinite(heading->get<double>()))
      throw Error(where + ": property '" + heading_name +
                  "' is not a number of degrees: " + heading->dump());
    s.heading_deg = heading->get<double>();
  }
  return s;
}

class Place : public CellOperator {
 public:
  const OperatorSpec& spec() const override {
    static const OperatorSpec s = place_spec();
    return s;
  }

  void run(const CellContext& ctx, CellData& data) const override {
    if (!data.wants("instances")) return;
    InstancesContent& out = data.content.instances_of("instances");
    const Tile<float>& dem = data.input("dem");
    const EllipsoidalHeights to_ellipsoid = ellipsoidal_heights(ctx.input_layer("dem"));
    const PixelFrame pixel(*ctx.grid, ctx.cell, dem.size());
    PrototypeLibrary models(*ctx.store);
    std::map<std::string, Ring> bases;  // by model, read once per cell
    for (const VectorFeature* f : data.features_of("strokes")) {
      if (!is_place_stroke(*f)) continue;
      const std::string where = "structures.place: feature " + std::to_string(f->id);
      const PlaceStroke stroke = place_stroke(*f, where);
      auto base = bases.find(stroke.model);
      if (base == bases.end()) {
        InstancesContent one;
        one.prototypes = {stroke.model};
        const MeshContent& model = *models.models(one, where).front();
        base =
            bases.emplace(stroke.model, model_base(model, where + ": model '" + stroke.model + "'"))
                .first;
      }
      const TangentPlaneRing plane = tangent_plane_ring(stroke.ring, where);
      PlaceOptions options;
      if (stroke.heading_deg) options.rotation = rotation_from_heading_deg(*stroke.heading_deg);
      const PlaceFit fit = fit_place(plane.ring, base->second, options, where);

      // The model's origin: the instance's position, its anchor (content.h).
      const EnuFrame plane_frame = enu_frame(plane.origin);
      const auto ground = [&](const Point2& p) {
        const GeodeticPoint g = plane_frame.to_geodetic(p[0], p[1], 0);
        return LonLat{g.lon, g.lat};
      };
      const LonLat origin = ground(fit.offset);
      if (!ctx.owns(origin)) continue;
      if (fit.outline_not_found)
        std::cerr << where << ": the stroke does not trace model '" << stroke.model
                  << "''s outline: placed by the stroke's axes and area only\n";
      // Its base stands on the lowest terrain under the placed base, as a building's does
      // (terrain_base.h): on a slope nothing floats.
      PixelRing base_pixels;
      const double cos_r = std::cos(fit.rotation), sin_r = std::sin(fit.rotation);
      for (const Point2& p : base->second)
        base_pixels.push_back(
            pixel(*ctx.grid, ground({fit.offset[0] + fit.scale * (cos_r * p[0] - sin_r * p[1]),
                                     fit.offset[1] + fit.scale * (sin_r * p[0] + cos_r * p[1])})));
      std::optional<float> terrain;
      try {
        terrain = lowest_terrain(dem, {base_pixels});
      } catch (const InvalidFootprint& e) {
        throw Error(where + ": the model's placed base is too large for the cell: " + e.what());
      }
      if (!terrain)
        throw Error(where + ": the DEM has no data under the model's base at (" +
                    std::to_string(origin.lon) + ", " + std::to_string(origin.lat) + ")");
      const double lon = origin.lon, lat = origin.lat;
      const EnuOrigin position{lon, lat, to_ellipsoid({lon, lat}, *terrain)};

      // Turned about the up of the position's own east-north-up frame, then in the content's.
      const EnuTransform to_content(position, out.origin);
      const std::array<double, 3> p = to_content.point(0, 0, 0);
      const std::array<double, 4> q =
          to_content.rotation(0, 0, std::sin(fit.rotation / 2), std::cos(fit.rotation / 2));
      out.prototype.push_back(uint16_t(prototype_index(out, stroke.model)));
      out.position.insert(out.position.end(), {float(p[0]), float(p[1]), float(p[2])});
      out.rotation.insert(out.rotation.end(), {float(q[0]), float(q[1]), float(q[2]), float(q[3])});
      out.scale.insert(out.scale.end(), 3, float(fit.scale));
      out.colour.push_back(0xffffffffu);  // the model's own colours
      ObjectProvenance& provenance = out.provenance.emplace_back();
      provenance.object_id = uint64_t(f->id);
      provenance.feature_id = f->id;
      provenance.tool = "structures.place";
      provenance.attributes = {{"axis_ratio", fit.axis_ratio},
                               {"half_turn_decided", fit.half_turn_decided}};
    }
  }

 private:
  static size_t prototype_index(InstancesContent& content, const std::string& name) {
    for (size_t i = 0; i < content.prototypes.size(); ++i)
      if (content.prototypes[i] == name) return i;
    content.prototypes.push_back(name);
    return content.prototypes.size() - 1;
  }
};

}  // namespace

std::unique_ptr<Operator> make_place() { return std::make_unique<Place>(); }

}  // namespace maquette::structures
