#include <GeographicLib/LocalCartesian.hpp>
#include <cmath>
#include <sstream>

#include "core/error.h"
#include "core/halo.h"
#include "operators.h"
#include "stroke.h"
#include "water_body.h"
#include "water_mesh.h"
#include "water_stroke.h"

namespace maquette::deform {
namespace {

OperatorSpec water_spec() {
  OperatorSpec s;
  s.name = "deform.water";
  s.description =
      "Bodies of water in closed strokes (tool 'water'): the lake below the spill level, a given "
      "level or a boundary percentile, as a water-depth raster and closed meshes";
  s.kind = OperatorKind::Region;
  InputSpec dem;
  dem.name = "dem";
  dem.description = "terrain heights (m)";
  s.inputs.push_back(dem);
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
  mesh.description = "one closed mesh per lake: top at the level, walls, bottom on the terrain";
  mesh.kind = LayerKind::Mesh;
  s.outputs.push_back(mesh);
  s.params_schema = {
      {"type", "object"}, {"properties", json::object()}, {"additionalProperties", false}};
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

// The lake's closed mesh (water_mesh.h) in the content of the cell owning its first vertex, in
// that content's east-north-up frame; its provenance carries the level, area and volume. Heights
// are the DEM's, taken as heights above the ellipsoid.
void add_mesh(const StepContext& ctx, const Mosaic& input, Mosaic& output, const VectorFeature& f,
              const BasinRaster& basin, const WaterBody& body) {
  const LakeMesh lake = lake_mesh(basin, body);
  // Corner (col, row) of the mosaic in the grid's plane, from any of the step's cells.
  const CellId cell = output.content.begin()->first;
  const PlaneSquare square = ctx.grid->plane_square(cell);
  const int64_t tile = int64_t(1) << (input.level - cell.level());
  const double pixel = square.side / double(tile);
  const double col0 = double(input.origin_col - int64_t(cell.col()) * tile);
  const double row0 = double(input.origin_row - int64_t(cell.row()) * tile);
  const auto corner_lon_lat = [&](const LakeVertex& v) {
    return ctx.grid->inverse(
        {square.x_min + (col0 + v.col) * pixel, square.y_max - (row0 + v.row) * pixel});
  };
  const LonLat anchor = corner_lon_lat(lake.vertices.front());
  const auto owner = output.content.find(ctx.grid->cell_from_point(anchor, cell.level()));
  if (owner == output.content.end())
    throw Error(describe(f) + ": the lake's mesh is anchored at " + lonlat_text(anchor) +
                ", outside the step's cells");
  MeshContent& mesh = owner->second.mesh("mesh");
  const GeographicLib::LocalCartesian frame(mesh.origin.lat, mesh.origin.lon, mesh.origin.height);
  MeshObject object;
  object.provenance = {
      uint64_t(f.id),
      f.id,
      "deform.water",
      {{"level", body.level}, {"area_m2", body.area_m2}, {"volume_m3", body.volume_m3}}};
  for (const LakeVertex& v : lake.vertices) {
    const LonLat p = corner_lon_lat(v);
    double x = 0, y = 0, z = 0;
    frame.Forward(p.lat, p.lon, v.height, x, y, z);
    object.positions.insert(object.positions.end(), {float(x), float(y), float(z)});
  }
  object.indices = lake.indices;
  mesh.objects.push_back(std::move(object));
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
    for (const VectorFeature* f : strokes) {
      if (!is_water_stroke(*f)) continue;
      if (centres.empty()) {  // once, for the first water stroke
        for (int r = 0; r < side; ++r)
          for (int c = 0; c < side; ++c) {
            centres.push_back(pixel_centre(
                *ctx.grid, {input.face, input.origin_col + c, input.origin_row + r}, input.level));
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
      if (!body.wet.empty() && !output.content.empty() &&
          output.content.begin()->second.wants("mesh"))
        add_mesh(ctx, input, output, *f, basin, body);
      for (size_t k = 0; depth != output.layers.end() && k < body.wet.size(); ++k)
        depth->second.at(int(body.wet[k] % side), int(body.wet[k] / side)) = body.depth[k];
    }
  }
};

}  // namespace

std::unique_ptr<Operator> make_water() { return std::make_unique<Water>(); }

}  // namespace maquette::deform
