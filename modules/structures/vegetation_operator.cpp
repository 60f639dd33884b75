// structures.vegetation (README.md): plants in closed strokes as an instances layer.
#include <Eigen/Geometry>
#include <algorithm>
#include <string>
#include <vector>

#include "content/enu_transform.h"
#include "core/enu_frame.h"
#include "core/error.h"
#include "core/splitmix64.h"
#include "core/tile_bilinear.h"
#include "gdal/vertical_datum.h"
#include "operators.h"
#include "poisson_disk.h"
#include "runtime/params_schema.h"
#include "vegetation_plant.h"
#include "vegetation_random.h"
#include "vegetation_stroke.h"

namespace maquette::structures {
namespace {

constexpr const char* kTool = "structures.vegetation";
constexpr int kWindowBuckets = 256;

OperatorSpec vegetation_spec() {
  OperatorSpec s;
  s.name = kTool;
  s.description =
      "Plants in closed strokes (tool 'vegetation', paper 002 §5): blue noise at the stroke's "
      "spacing_m, coloured from the orthophoto, based on the DEM, as instances";
  s.kind = OperatorKind::Cell;
  s.halo = 1;  // the bilinear height and the 3 x 3 colour of plants near the cell's edge
  s.inputs = {single_channel_input(
                  "dem", "terrain heights (m, on the layer's vertical datum): the plants' base",
                  Semantics::Continuous),
              {"orthophoto", "imagery, bands 1-3 red, green, blue in 0..255: the plants' colour"},
              strokes_input()};
  OutputSpec plants;
  plants.name = "plants";
  plants.description = "one instance per plant, its provenance the stroke";
  plants.kind = LayerKind::Instances;
  s.outputs.push_back(plants);
  const json range = {{"type", "array"}, {"items", {{"type", "number"}}}};
  json scale = range, heading = range;
  scale["default"] = {8, 15};  // the built-in prototypes are 1 m tall: trees of 8 to 15 m
  heading["default"] = {0, 360};
  s.params_schema = {
      {"type", "object"},
      {"properties",
       {{"placement",
         {{"type", "string"}, {"enum", {"poisson", "random"}}, {"default", "poisson"}}},
        {"seed", {{"type", "integer"}, {"minimum", 0}, {"default", 0}}},
        {"prototypes",
         {{"type", "array"},
          {"items",
           {{"type", "object"},
            {"properties",
             {{"name", {{"type", "string"}}},
              {"weight", {{"type", "number"}, {"minimum", 0}, {"default", 1}}}}},
            {"required", {"name"}},
            {"additionalProperties", false}}},
          {"default", {{{"name", "builtin:broadleaf"}, {"weight", 1}}}}}},
        {"scale", scale},
        {"heading_deg", heading},
        {"spacings", named_param(NamedKind::Artifact, "",
                                 "artifact of structures.vegetation_spacing giving the strokes "
                                 "without spacing_m theirs")}}},
      {"additionalProperties", false}};
  return s;
}

// Where the cell's plants of a stroke can be, in the stroke's plane: the cell's bounding box (its
// boundary's points, grown for the bulge of its edges between them: a cell's edge is straight in
// the grid's plane, not here; 1 m and a thousandth of the box) clipped to the stroke's. The
// plants do not depend on the window (poisson_disk.h): clipping only saves the darts of a small
// stroke in a large cell.
PlaneWindow cell_window(const std::vector<LonLat>& boundary, const VegetationStroke& stroke) {
  PlaneWindow w{1e300, 1e300, -1e300, -1e300};
  for (const LonLat& p : boundary) {
    const PlanePoint q = stroke.to_plane(p);
    w = {std::min(w.x_min, q.x), std::min(w.y_min, q.y), std::max(w.x_max, q.x),
         std::max(w.y_max, q.y)};
  }
  const double margin = 1 + 1e-3 * std::max(w.x_max - w.x_min, w.y_max - w.y_min);
  PlaneWindow s{1e300, 1e300, -1e300, -1e300};
  for (const auto& polygon : stroke.polygons)
    for (const PlanePoint2& q : polygon.front())
      s = {std::min(s.x_min, q[0]), std::min(s.y_min, q[1]), std::max(s.x_max, q[0]),
           std::max(s.y_max, q[1])};
  return {std::max(w.x_min - margin, s.x_min), std::max(w.y_min - margin, s.y_min),
          std::min(w.x_max + margin, s.x_max), std::min(w.y_max + margin, s.y_max)};
}

// The stroke's plants in `window`: blue noise, or the paper's placement (every plant of the
// stroke, then those in the window).
std::vector<PlanePoint> placed(const VegetationParams& params, const VegetationStroke& stroke,
                               const PlaneWindow& window) {
  const uint64_t seed = splitmix64_mix(params.seed ^ splitmix64_mix(uint64_t(stroke.feature->id)));
  std::vector<PlanePoint> out;
  if (!params.random) {
    // In windows of kWindowBuckets buckets a side: the same points (poisson_disk.h), in bounded
    // memory (~5 MB a window, where a 10 km cell at 2 m would take 1.6 GB) and faster (a window's
    // buckets stay in cache).
    const double r = poisson_min_distance(stroke.spacing_m), step = kWindowBuckets * r;
    for (double y = window.y_min; y < window.y_max; y += step)
      for (double x = window.x_min; x < window.x_max; x += step) {
        const auto part = poisson_disk(
            stroke.region, r, seed,
            {x, y, std::min(x + step, window.x_max), std::min(y + step, window.y_max)});
        out.insert(out.end(), part.begin(), part.end());
      }
    return out;
  }
  for (size_t k = 0; k < stroke.polygons.size(); ++k) {
    Footprint part;
    try {
      part = make_footprint(stroke.polygons[k]);
    } catch (const InvalidFootprint& e) {
      throw Error("inputs.strokes: feature " + std::to_string(stroke.feature->id) +
                  " (tool vegetation): part " + std::to_string(k) + ": " + e.what());
    }
    for (const PlanePoint& p : random_placement(part, stroke.spacing_m, seed + k))
      if (p.x >= window.x_min && p.x < window.x_max && p.y >= window.y_min && p.y < window.y_max)
        out.push_back(p);
  }
  return out;
}

// ctx.owns(ground) from the point's position g in the grid's plane: the cell is the square there,
// so a point well inside or outside it is decided at once, and only one within a rounding margin
// of its edge asks the grid (half the cost of a plant).
bool owned(const CellContext& ctx, const PlaneSquare& square, PlanePoint g, LonLat ground) {
  const double margin = 1e-9 * square.side;
  const double x = g.x - square.x_min, y = square.y_max - g.y;
  if (x < -margin || x > square.side + margin || y < -margin || y > square.side + margin)
    return false;
  if (x > margin && x < square.side - margin && y > margin && y < square.side - margin) return true;
  return ctx.owns(ground);
}

// Strokes without spacing_m take theirs from the artifact named by params.spacings (written by
// structures.vegetation_spacing), read once.
void resolve_spacings(const CellContext& ctx, std::vector<VegetationStroke>& strokes) {
  json spacings;
  for (VegetationStroke& stroke : strokes) {
    if (stroke.spacing_m > 0) continue;
    const std::string name = ctx.params->at("spacings").get<std::string>();
    const std::string id = std::to_string(stroke.feature->id);
    const std::string where = "inputs.strokes: feature " + id + " (tool vegetation)";
    if (name.empty())
      throw Error(where + ": field 'spacing_m' is missing: give it, or params.spacings (the " +
                  "artifact of structures.vegetation_spacing)");
    if (spacings.is_null()) {
      const auto artifact = ctx.store ? ctx.store->get_artifact(name) : std::nullopt;
      if (!artifact) throw Error("params.spacings: no artifact '" + name + "' in the store");
      spacings = json::parse(artifact->text(), nullptr, false);
    }
    const auto it = spacings.is_object() ? spacings.find(id) : spacings.end();
    if (it == spacings.end() || !it->is_number() || !(it->get<double>() > 0))
      throw Error(where + ": no spacing_m, and none in artifact '" + name +
                  "' (did structures.vegetation_spacing see the stroke's orthophoto?)");
    stroke.spacing_m = it->get<double>();
  }
}

// The params of a stroke's plants: the step's, with the stroke's own `prototypes` ({name:
// weight}, DESIGN.md's stroke convention) and `scale` ([min, max]) in their place when it has
// them. Throws maquette::Error naming the feature and field at fault.
VegetationParams stroke_params(const json& step, const VegetationParams& step_params,
                               const VegetationStroke& stroke) {
  const json& a = stroke.feature->attributes;
  const auto prototypes = a.find("prototypes"), scale = a.find("scale");
  if (prototypes == a.end() && scale == a.end()) return step_params;
  const std::string where =
      "inputs.strokes: feature " + std::to_string(stroke.feature->id) + " (tool vegetation)";
  json merged = step;
  if (prototypes != a.end()) {
    if (!prototypes->is_object() || prototypes->empty())
      throw Error(where + ": field 'prototypes' is " + prototypes->dump() +
                  ", not {name: weight, ...}");
    merged["prototypes"] = json::array();
    for (const auto& [name, weight] : prototypes->items()) {
      if (!weight.is_number() || !(weight.get<double>() >= 0))
        throw Error(where + ": field 'prototypes': the weight of '" + name + "' is " +
                    weight.dump() + ", not a number >= 0");
      merged["prototypes"].push_back({{"name", name}, {"weight", weight}});
    }
  }
  if (scale != a.end()) {
    if (!scale->is_array() || scale->size() != 2 || !(*scale)[0].is_number() ||
        !(*scale)[1].is_number())
      throw Error(where + ": field 'scale' is " + scale->dump() + ", not [min, max]");
    merged["scale"] = *scale;
  }
  try {
    return vegetation_params(merged);
  } catch (const Error& e) {
    throw Error(where + " (its own prototypes or scale): " + e.what());
  }
}

// Room for `more` instances beyond those in `out`, growing geometrically (strokes add in turn):
// the arrays are not copied as they grow, plant by plant.
void reserve_more(InstancesContent& out, size_t more) {
  const size_t n = out.size() + more;
  if (out.prototype.capacity() >= n) return;
  const size_t room = std::max(n, 2 * out.prototype.capacity());
  out.prototype.reserve(room);
  out.position.reserve(3 * room);
  out.rotation.reserve(4 * room);
  out.scale.reserve(3 * room);
  out.colour.reserve(room);
  out.provenance.reserve(room);
}

// The index of prototype `name` in the content's list, added when new.
uint16_t prototype_index(InstancesContent& content, const std::string& name) {
  const auto it = std::find(content.prototypes.begin(), content.prototypes.end(), name);
  if (it != content.prototypes.end()) return uint16_t(it - content.prototypes.begin());
  if (content.prototypes.size() > 65535)
    throw Error("structures.vegetation: more than 65,536 prototypes in one cell");
  content.prototypes.push_back(name);
  return uint16_t(content.prototypes.size() - 1);
}

class Vegetation : public CellOperator {
 public:
  const OperatorSpec& spec() const override {
    static const OperatorSpec s = vegetation_spec();
    return s;
  }

  void run(const CellContext& ctx, CellData& data) const override {
    if (!data.wants("plants")) return;
    std::vector<VegetationStroke> strokes =
        vegetation_strokes(data.features_of("strokes"), "strokes");
    if (strokes.empty()) return;
    resolve_spacings(ctx, strokes);
    const VegetationParams params = vegetation_params(*ctx.params);
    const Tile<float>& dem = data.input("dem");
    // The DEM's heights on its recorded vertical datum, to the ellipsoid content is placed on.
    const EllipsoidalHeights to_ellipsoid = ellipsoidal_heights(ctx.input_layer("dem"));
    const Tile<float>& orthophoto = data.input("orthophoto");
    if (orthophoto.channels() < 3)
      throw Error("inputs.orthophoto: " + std::to_string(orthophoto.channels()) +
                  " band(s), not red, green and blue");
    InstancesContent& out = data.content.instances_of("plants");
    out.prototypes = params.prototypes;
    const EnuFrame frame = enu_frame(out.origin);
    const std::vector<LonLat> boundary = ctx.grid->boundary(ctx.cell, 8);
    const PlaneSquare square = ctx.grid->plane_square(ctx.cell);
    const double pixel = square.side / ctx.tile_size;
    std::array<double, 9> m;  // a plant's east-north-up axes in the content's frame
    for (const VegetationStroke& stroke : strokes) {
      const VegetationParams own = stroke_params(*ctx.params, params, stroke);
      std::vector<uint16_t> index;  // of the stroke's prototypes in the content's
      for (const std::string& name : own.prototypes) index.push_back(prototype_index(out, name));
      const std::vector<PlanePoint> points = placed(own, stroke, cell_window(boundary, stroke));
      reserve_more(out, points.size());  // at most: some are other cells'
      for (const PlanePoint& p : points) {
        const LonLat ground = stroke.to_ground(p);
        const PlanePoint g = ctx.grid->forward(ground);
        if (!owned(ctx, square, g, ground)) continue;
        const double col = (g.x - square.x_min) / pixel - 0.5;
        const double row = (square.y_max - g.y) / pixel - 0.5;
        const double terrain = bilinear(dem, col, row);
        if (std::isnan(terrain)) continue;  // no terrain: no plant
        const double height = to_ellipsoid(ground, terrain);
        const PlantLook look = plant_look(own, stroke.feature->id, p);
        const auto [x, y, z] = frame.to_enu(ground.lon, ground.lat, height, m);
        const Eigen::Quaterniond q =
            Eigen::Quaterniond(
                Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(m.data())) *
            Eigen::AngleAxisd(look.heading_rad, Eigen::Vector3d::UnitZ());
        out.prototype.push_back(index[look.prototype]);
        out.position.insert(out.position.end(), {float(x), float(y), float(z)});
        out.rotation.insert(out.rotation.end(),
                            {float(q.x()), float(q.y()), float(q.z()), float(q.w())});
        out.scale.insert(out.scale.end(), {look.scale, look.scale, look.scale});
        out.colour.push_back(
            neighbourhood_colour(orthophoto, int(std::lround(col)), int(std::lround(row))));
        out.provenance.push_back({look.id, stroke.feature->id, kTool, json::object()});
      }
    }
  }
};

}  // namespace

std::unique_ptr<Operator> make_vegetation() { return std::make_unique<Vegetation>(); }

}  // namespace maquette::structures
