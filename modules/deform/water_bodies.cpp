// deform.water_bodies: per water stroke, the wet pixels (depth > 0) whose centres lie in it,
// summed over cells: area and volume from the grid's equal pixel areas, the level as the highest
// terrain + depth (deform.water's level within float32 rounding). Strokes sharing a wet pixel are
// an error (claim_pixel, water_stroke.h), as in deform.water: no water is counted twice.
#include <algorithm>
#include <cmath>

#include "core/halo.h"
#include "operators.h"
#include "water_stroke.h"

namespace maquette::deform {
namespace {

OperatorSpec bodies_spec() {
  OperatorSpec s;
  s.name = "deform.water_bodies";
  s.description =
      "Each water stroke's body from deform.water's depth: feature id, level (m), area (m2) and "
      "volume (m3), as a JSON artifact";
  s.kind = OperatorKind::Reduce;
  s.inputs.push_back(single_channel_input("dem", "terrain heights (m)", Semantics::Continuous));
  s.inputs.push_back(single_channel_input("depth", "water depth (m)", Semantics::Continuous));
  InputSpec strokes;
  strokes.name = "strokes";
  strokes.description = "features layer: Polygon strokes with tool 'water'";
  strokes.kind = LayerKind::Features;
  s.inputs.push_back(strokes);
  OutputSpec bodies;
  bodies.name = "bodies";
  bodies.description = "JSON artifact: [{feature, level, area_m2, volume_m3}] by feature id";
  s.outputs.push_back(bodies);
  s.params_schema = {
      {"type", "object"}, {"properties", json::object()}, {"additionalProperties", false}};
  return s;
}

class WaterBodies : public ReduceOperator {
 public:
  const OperatorSpec& spec() const override {
    static const OperatorSpec s = bodies_spec();
    return s;
  }

  // {"<feature id>": {"pixels", "depth_sum", "level", "pixel_area_m2"}} for the strokes wet here.
  json map(const CellContext& ctx, const CellData& data) const override {
    const Tile<float>& dem = data.input("dem");
    const Tile<float>& depth = data.input("depth");
    const int n = ctx.tile_size;
    const int level = ctx.cell.level() + int(std::lround(std::log2(n)));
    json partial = json::object();
    std::vector<const VectorFeature*> owner(size_t(n) * size_t(n), nullptr);
    for (const VectorFeature* f : data.features_of("strokes")) {
      if (!is_water_stroke(*f)) continue;
      const PolygonSet polygon = stroke_polygon(*f);
      int64_t pixels = 0;
      double sum = 0, top = -INFINITY;
      for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) {
          const float d = depth.at(c, r);
          if (!(d > 0)) continue;
          const FaceCoord p{ctx.cell.face(), int64_t(ctx.cell.col()) * n + c,
                            int64_t(ctx.cell.row()) * n + r};
          const LonLat centre = pixel_centre(*ctx.grid, p, level);
          if (!polygon.contains(centre)) continue;
          claim_pixel(owner, size_t(r) * size_t(n) + size_t(c), *f, centre);
          ++pixels;
          sum += double(d);
          top = std::max(top, double(dem.at(c, r)) + double(d));
        }
      if (pixels > 0)
        partial[std::to_string(f->id)] = {
            {"pixels", pixels},
            {"depth_sum", sum},
            {"level", top},
            {"pixel_area_m2", ctx.grid->area(0) / std::ldexp(1.0, 2 * level)}};
    }
    return partial.empty() ? json() : partial;
  }

  json merge(const json& a, const json& b) const override {
    if (a.is_null()) return b;
    json out = a;
    for (const auto& [id, v] : b.items()) {
      if (!out.contains(id)) {
        out[id] = v;
        continue;
      }
      json& o = out[id];
      o["pixels"] = o["pixels"].get<int64_t>() + v["pixels"].get<int64_t>();
      o["depth_sum"] = o["depth_sum"].get<double>() + v["depth_sum"].get<double>();
      o["level"] = std::max(o["level"].get<double>(), v["level"].get<double>());
    }
    return out;
  }

  Artifact finish(const json& merged, const StepContext&) const override {
    json bodies = json::array();
    if (!merged.is_null())
      for (const auto& [id, v] : merged.items()) {
        const double area = v["pixel_area_m2"].get<double>();
        bodies.push_back({{"feature", std::stoll(id)},
                          {"level", v["level"]},
                          {"area_m2", double(v["pixels"].get<int64_t>()) * area},
                          {"volume_m3", v["depth_sum"].get<double>() * area}});
      }
    std::sort(bodies.begin(), bodies.end(), [](const json& x, const json& y) {
      return x["feature"].get<int64_t>() < y["feature"].get<int64_t>();
    });
    return Artifact::FromText("", bodies.dump(2));
  }
};

}  // namespace

std::unique_ptr<Operator> make_water_bodies() { return std::make_unique<WaterBodies>(); }

}  // namespace maquette::deform
