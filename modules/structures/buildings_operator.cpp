#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>
#include <string>

#include "building_mesh.h"
#include "content/facet_normals.h"
#include "core/error.h"
#include "footprint.h"
#include "gltf/texture_image.h"
#include "operators.h"

namespace maquette::structures {
namespace {

OperatorSpec buildings_spec() {
  OperatorSpec s;
  s.name = "structures.buildings";
  s.description =
      "Buildings from footprints (paper 002 §7, Fig. 15): walls from the lowest terrain under "
      "them up to their roofs by their OSM height and roof tags (flat, gabled, hipped, pyramidal, "
      "skillion), courtyards kept, checked as val3dity checks solids";
  s.kind = OperatorKind::Cell;
  s.halo = kDemHaloPixels;
  s.inputs.push_back(single_channel_input(
      "dem", "terrain heights (m above the layer's vertical datum)", Semantics::Continuous));
  InputSpec orthophoto;
  orthophoto.name = "orthophoto";
  orthophoto.description = "imagery (grey, RGB or RGBA, 0-255) the roofs drape";
  orthophoto.optional = true;
  s.inputs.push_back(orthophoto);
  InputSpec footprints;
  footprints.name = "footprints";
  footprints.description = "features layer: Polygons or MultiPolygons, holes for courtyards";
  footprints.kind = LayerKind::Features;
  s.inputs.push_back(footprints);
  OutputSpec mesh;
  mesh.name = "mesh";
  mesh.description = "one closed mesh per footprint, in the cell owning its first point";
  mesh.kind = LayerKind::Mesh;
  s.outputs.push_back(mesh);
  s.params_schema = {{"type", "object"},
                     {"properties",
                      {{"default_height_m",
                        {{"type", "number"}, {"minimum", 0.1}, {"maximum", 1000}, {"default", 10}}},
                       {"level_height_m",
                        {{"type", "number"}, {"minimum", 0.1}, {"maximum", 100}, {"default", 3}}},
                       {"skip_invalid", {{"type", "boolean"}, {"default", false}}}}},
                     {"additionalProperties", false}};
  return s;
}

// The cell's orthophoto tile with its halo (the texture window of building_mesh.h) as the
// material of the cell's buildings: JPEG for RGB, PNG otherwise; no data black.
Material orthophoto_material(const Tile<float>& orthophoto) {
  const int halo = orthophoto.halo(), width = orthophoto.size() + 2 * halo;
  Tile<uint8_t> image(width, orthophoto.channels());
  for (int r = 0; r < width; ++r)
    for (int c = 0; c < width; ++c)
      for (int k = 0; k < orthophoto.channels(); ++k) {
        const float v = orthophoto.at(c - halo, r - halo, k);
        image.at(c, r, k) = std::isnan(v) ? 0 : uint8_t(std::lround(std::clamp(v, 0.0f, 255.0f)));
      }
  const EncodedImage encoded = encode_texture(image);
  Material m;
  m.name = "orthophoto";
  m.image.assign(encoded.bytes.begin(), encoded.bytes.end());
  m.image_mime = encoded.mime_type;
  return m;
}

std::optional<GeoPoint> first_point(const Geometry& g) {
  if (!g.polygons.empty() && !g.polygons[0].rings.empty() && !g.polygons[0].rings[0].empty())
    return g.polygons[0].rings[0][0];
  if (!g.lines.empty() && !g.lines[0].empty()) return g.lines[0][0];
  if (!g.points.empty()) return g.points[0];
  return std::nullopt;
}

class Buildings : public CellOperator {
 public:
  const OperatorSpec& spec() const override {
    static const OperatorSpec s = buildings_spec();
    return s;
  }

  void run(const CellContext& ctx, CellData& data) const override {
    if (!data.wants("mesh")) return;
    const json& params = *ctx.params;
    const HeightRules rules{params.at("default_height_m").get<double>(),
                            params.at("level_height_m").get<double>()};
    const bool skip_invalid = params.at("skip_invalid").get<bool>();
    MeshContent& mesh = data.content.mesh("mesh");
    // Set up with the cell's first building: PROJ's transformation costs a few milliseconds.
    std::optional<EllipsoidalHeights> to_ellipsoid;
    BuildingSite site{ctx.grid, ctx.cell, &data.input("dem"), mesh.origin, std::nullopt};
    const auto orthophoto = data.inputs.find("orthophoto");
    if (orthophoto != data.inputs.end())
      site.texture = TextureWindow{orthophoto->second.size(), orthophoto->second.halo()};
    for (const VectorFeature* f : data.features_of("footprints")) {
      // Each building once: in the cell owning its first point (a feature of another geometry
      // is reported there too, by building_mesh).
      if (const std::optional<GeoPoint> first = first_point(f->geometry);
          !first || !ctx.owns({first->lon, first->lat}))
        continue;
      if (!to_ellipsoid) {
        to_ellipsoid.emplace(ellipsoidal_heights(ctx.input_layer("dem")));
        site.to_ellipsoid = &*to_ellipsoid;
      }
      try {
        std::string warning;
        MeshObject object = building_mesh(*f, rules, site, &warning);
        if (!warning.empty())
          std::cerr << "structures.buildings: inputs.footprints: feature " << f->id << ": "
                    << warning << "\n";
        if (site.texture) {
          if (mesh.materials.empty())
            mesh.materials.push_back(orthophoto_material(orthophoto->second));
          object.material = 0;
        }
        mesh.objects.push_back(with_facet_normals(object));
      } catch (const InvalidFootprint& e) {
        const std::string message = "structures.buildings: inputs.footprints: feature " +
                                    std::to_string(f->id) + ": " + e.what();
        if (!skip_invalid) throw Error(message + " (skip_invalid: true leaves it out)");
        std::cerr << message << ": left out\n";
      }
    }
  }
};

}  // namespace

std::unique_ptr<Operator> make_buildings() { return std::make_unique<Buildings>(); }

}  // namespace maquette::structures
