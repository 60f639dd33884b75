// structures.vegetation_spacing (README.md): the spacing of strokes without spacing_m, from the
// orthophoto's tiles inside each (spacing_estimate.h, their rings summed), as an artifact
// {"<feature id>": spacing in metres} for structures.vegetation's params.spacings.
#include <bit>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "core/enu_frame.h"
#include "core/error.h"
#include "core/halo.h"
#include "operators.h"
#include "spacing_estimate.h"
#include "vegetation_stroke.h"

namespace maquette::structures {
namespace {

constexpr const char* kOp = "structures.vegetation_spacing";

OperatorSpec spacing_spec() {
  OperatorSpec s;
  s.name = kOp;
  s.description =
      "The plants' spacing of vegetation strokes without spacing_m, from the orthophoto's "
      "power spectrum inside each (paper 002 §5's 'provided automatically'), as an artifact";
  s.kind = OperatorKind::Reduce;
  s.inputs = {{"orthophoto", "imagery (red, green, blue, or one band): its luminance is analysed"},
              strokes_input()};
  OutputSpec spacings;
  spacings.name = "spacings";
  spacings.description = "artifact (JSON): {\"<feature id>\": spacing_m}";
  s.outputs.push_back(spacings);
  s.params_schema = {
      {"type", "object"}, {"properties", json::object()}, {"additionalProperties", false}};
  return s;
}

// The centre of pixel (col, row) of the cell's tile of side n.
LonLat centre(const CellContext& ctx, int n, int col, int row) {
  return pixel_centre(
      *ctx.grid,
      {ctx.cell.face(), int64_t(ctx.cell.col()) * n + col, int64_t(ctx.cell.row()) * n + row},
      ctx.cell.level() + std::countr_zero(unsigned(n)));
}

// The pixel steps on the ground at the tile's middle (metres east and north).
PixelAxes tile_axes(const CellContext& ctx, int n) {
  const LonLat o = centre(ctx, n, n / 2, n / 2);
  const EnuFrame frame({o.lon, o.lat, 0});
  const auto step = [&](int col, int row) {
    const LonLat p = centre(ctx, n, col, row);
    const auto [x, y, z] = frame.to_enu(p.lon, p.lat);
    return std::pair(x, y);
  };
  const auto [ce, cn] = step(n / 2 + 1, n / 2);
  const auto [re, rn] = step(n / 2, n / 2 + 1);
  return {ce, cn, re, rn};
}

// The luminance of the tile's pixels inside the stroke, NaN elsewhere; empty when none is.
std::vector<float> luminance_inside(const CellContext& ctx, const Tile<float>& tile,
                                    const VegetationStroke& stroke) {
  const int n = tile.size();
  std::vector<float> out(size_t(n) * size_t(n), NAN);
  bool any = false;
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) {
      const PlanePoint q = stroke.to_plane(centre(ctx, n, c, r));
      if (!stroke.region.contains({q.x, q.y})) continue;
      const float v = tile.channels() >= 3 ? 0.299f * tile.at(c, r, 0) + 0.587f * tile.at(c, r, 1) +
                                                 0.114f * tile.at(c, r, 2)
                                           : tile.at(c, r);
      out[size_t(r) * size_t(n) + size_t(c)] = v;
      any = any || std::isfinite(v);
    }
  return any ? out : std::vector<float>();
}

class VegetationSpacing : public ReduceOperator {
 public:
  const OperatorSpec& spec() const override {
    static const OperatorSpec s = spacing_spec();
    return s;
  }

  // {"<feature id>": {"side": n, "pixel_m": .., "power": [...], "count": [...]}} of the cell's
  // tile; pixel_m: the side of the pixels' area (rHEALPix pixels are equal-area, not square:
  // the rings are in metres through each tile's PixelAxes).
  json map(const CellContext& ctx, const CellData& data) const override {
    json partial = json::object();
    const Tile<float>& tile = data.input("orthophoto");
    for (const VegetationStroke& stroke :
         vegetation_strokes(data.features_of("strokes"), "strokes")) {
      if (stroke.spacing_m > 0) continue;
      const std::vector<float> image = luminance_inside(ctx, tile, stroke);
      if (image.empty()) continue;
      const PixelAxes axes = tile_axes(ctx, tile.size());
      partial[std::to_string(stroke.feature->id)] =
          to_json(ring_power(image, tile.size(), tile.size(), axes), axes.area_side());
    }
    return partial;
  }

  json merge(const json& a, const json& b) const override {
    json out = a.is_object() ? a : json::object();
    if (!b.is_object()) return out;
    for (const auto& [id, rings] : b.items()) {
      if (!out.contains(id)) {
        out[id] = rings;
        continue;
      }
      RingPower sum = from_json(out[id]);
      add_rings(sum, from_json(rings));
      out[id] = to_json(sum, rings.at("pixel_m").get<double>());
    }
    return out;
  }

  Artifact finish(const json& merged, const StepContext&) const override {
    json spacings = json::object();
    if (merged.is_object())
      for (const auto& [id, rings] : merged.items()) {
        try {
          spacings[id] = spacing_from_rings(from_json(rings), rings.at("pixel_m").get<double>());
        } catch (const std::runtime_error& e) {
          throw Error(std::string(kOp) + ": inputs.strokes: feature " + id + ": " + e.what());
        }
      }
    return Artifact::FromText("", spacings.dump(), {{"kind", kOp}});
  }

 private:
  static json to_json(const RingPower& rings, double pixel_m) {
    return {
        {"side", rings.side}, {"pixel_m", pixel_m}, {"power", rings.power}, {"count", rings.count}};
  }
  static RingPower from_json(const json& j) {
    return {j.at("side").get<int>(), j.at("power").get<std::vector<double>>(),
            j.at("count").get<std::vector<double>>()};
  }
};

}  // namespace

std::unique_ptr<Operator> make_vegetation_spacing() {
  return std::make_unique<VegetationSpacing>();
}

}  // namespace maquette::structures
