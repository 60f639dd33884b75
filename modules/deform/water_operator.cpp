#include <cmath>
#include <sstream>

#include "core/error.h"
#include "core/mosaic_geometry.h"
#include "operators.h"
#include "stroke.h"
#include "water_body.h"
#include "water_content.h"
#include "water_stroke.h"

namespace maquette::deform {
namespace {

OperatorSpec water_spec() {
  OperatorSpec s;
  s.name = "deform.water";
  s.description =
      "Bodies of water in closed strokes (tool 'water'): the lake below the spill level, a given "
      "level or a boundary percentile, as a water-depth raster, closed meshes and fog volumes";
  s.kind = OperatorKind::Region;
  // Pixel centres and the lake's corners are placed through the unfolded plane.
  s.spans_faces = true;
  s.inputs.push_back(single_channel_input("dem", "terrain heights (m)", Semantics::Continuous));
  InputSpec strokes;
  strokes.name = "strokes";
  strokes.description = "features layer: Polygon strokes with tool 'water'";
  strokes.kind = LayerKind::Features;
  s.inputs.push_back(strokes);
  OutputSpec depth;
  depth.name = "depth";
  depth.description = "water depth (m): 0 on dry land, nodata where the DEM has none";
  depth.units = "m";
  s.outputs.push_back(depth);
  OutputSpec mesh;
  mesh.name = "mesh";
  mesh.description =
      "one closed mesh per lake: top at the level, walls, a flat bottom below the lowest bed";
  mesh.kind = LayerKind::Mesh;
  s.outputs.push_back(mesh);
  OutputSpec volume;
  volume.name = "volume";
  volume.description =
      "one OpenVDB fog volume per lake (grid \"water\"): the water from its bed to its level";
  volume.kind = LayerKind::Volume;
  s.outputs.push_back(volume);
  s.params_schema = {{"type", "object"},
                     {"properties",
                      {{"colour",
                        {{"type", "array"},
                         {"items", {{"type", "number"}, {"minimum", 0}, {"maximum", 1}}},
                         {"default", kWaterSrgb},
                         {"description", "the lakes' colour: sRGB [r, g, b] in 0..1"}}}}},
                     {"additionalProperties", false}};
  return s;
}

std::string metres(double v) {
  std::ostringstream s;
  s.precision(9);
  s << v << " m";
  return s.str();
}

// The pixels of `mosaic` whose centres lie in the stroke's polygon; the stroke must not reach
// the mosaic's edge (its water could leave the region unseen).
std::vector<uint8_t> inside_pixels(const VectorFeature& f, const std::vector<LonLat>& centres,
                                   int side) {
  const PolygonSet polygon = stroke_polygon(f);
  std::vector<uint8_t> inside(centres.size());
  for (size_t i = 0; i < centres.size(); ++i) inside[i] = polygon.contains(centres[i]);
  for (int k = 0; k < side; ++k)
    for (const size_t i : {size_t(k), size_t(side - 1) * size_t(side) + size_t(k),
                           size_t(k) * size_t(side), size_t(k) * size_t(side) + size_t(side - 1)})
      if (inside[i])
        throw Error(describe(f) + " reaches the edge of the region's DEM at " +
                    lonlat_text(centres[i]) + ": the region must hold the whole stroke");
  return inside;
}

// The step's `colour` (the schema checked its components).
std::array<double, 3> colour(const json& params) {
  const json& c = params.at("colour");
  if (c.size() != 3)
    throw Error("deform.water: params.colour: expected 3 numbers (sRGB r, g, b in 0..1), got " +
                c.dump());
  return {c[0].get<double>(), c[1].get<double>(), c[2].get<double>()};
}

class Water : public RegionOperator {
 public:
  const OperatorSpec& spec() const override {
    static const OperatorSpec s = water_spec();
    return s;
  }

  void run(const StepContext& ctx, const Mosaic& input, Mosaic& output) const override {
    const Tile<float>& dem = input.layers.at("dem");
    const int side = dem.size();
    const auto depth = output.layers.find("depth");  // when the step maps it
    if (depth != output.layers.end())
      for (int r = 0; r < side; ++r)
        for (int c = 0; c < side; ++c)
          depth->second.at(c, r) = std::isnan(dem.at(c, r)) ? NAN : 0.0f;

    const FeatureList& strokes = input.features.at("strokes");
    std::vector<LonLat> centres;
    std::vector<float> terrain;
    std::vector<const VectorFeature*> owner(size_t(side) * size_t(side), nullptr);
    LakeContent lakes(ctx, input, output, water_material(colour(*ctx.params)));
    for (const VectorFeature* f : strokes) {
      if (!is_water_stroke(*f)) continue;
      if (centres.empty()) {  // once, for the first water stroke
        // The mosaic may span faces (core/unfolded_faces.h): a sample in a corner gap of the
        // unfolded plane has no centre (NaN: in no polygon) and no terrain.
        const MosaicGeometry samples(*ctx.grid, input.face, input.level, input.origin_col,
                                     input.origin_row);
        for (int r = 0; r < side; ++r)
          for (int c = 0; c < side; ++c) {
            centres.push_back(samples.sample_lonlat(c, r).value_or(LonLat{NAN, NAN}));
            terrain.push_back(dem.at(c, r));
          }
      }
      const std::vector<uint8_t> inside = inside_pixels(*f, centres, side);
      for (size_t i = 0; i < inside.size(); ++i)
        if (inside[i]) claim_pixel(owner, i, *f, centres[i]);
      // rHEALPix pixels are equal-area: the face's area over its pixel count.
      const BasinRaster basin{side, side, terrain, inside,
                              ctx.grid->area(0) / std::ldexp(1.0, 2 * input.level)};
      const std::string where = describe(*f);
      const WaterLevel rule = WaterLevel::from_attributes(f->attributes, where);
      const double level = [&] {
        try {
          return water_level(basin, rule);
        } catch (const Error& e) {
          throw Error(where + ": " + e.what());
        }
      }();
      const WaterBody body = fill_basin(basin, level);
      if (body.leak)
        throw Error(where + ": at level " + metres(body.level) +
                    " the water leaks out of the stroke at " +
                    lonlat_text(centres[size_t(*body.leak)]) +
                    ": lower the level or draw the stroke around the basin");
      if (!body.wet.empty() && !output.content.empty()) lakes.add(*f, basin, body);
      for (size_t k = 0; depth != output.layers.end() && k < body.wet.size(); ++k)
        depth->second.at(int(body.wet[k] % side), int(body.wet[k] / side)) = body.depth[k];
    }
    lakes.finish();
  }
};

}  // namespace

std::unique_ptr<Operator> make_water() { return std::make_unique<Water>(); }

}  // namespace maquette::deform
