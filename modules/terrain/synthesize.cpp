// terrain.synthesize: the synthetic terrain of synthetic_terrain.h sampled at the pixel centres.
#include "core/halo.h"
#include "operators.h"
#include "runtime/params_schema.h"
#include "synthetic_terrain.h"

namespace maquette::terrain {
namespace {

OperatorSpec synthesize_spec() {
  OperatorSpec s;
  s.name = "terrain.synthesize";
  s.description =
      "Deterministic synthetic terrain (fractal 3D noise of the position with ridges, sea "
      "clamped to 0 m), seamless across tiles and faces";
  s.kind = OperatorKind::Cell;
  s.outputs = {{"dem", "elevation", DType::F32, 1, Semantics::Continuous, "m", std::nullopt}};
  s.params_schema = {
      {"type", "object"},
      {"additionalProperties", false},
      // Relief beyond 20 km is no longer terrain, and a wavelength beyond 20000 km is longer than
      // half the globe's circumference.
      {"properties",
       {{"seed", {{"type", "integer"}, {"default", 1}, {"description", "noise seed"}}},
        {"amplitude_m", number_param(0, 20000, 2500, "scale of the relief, metres")},
        {"octaves", integer_param(1, 24, 7, "noise octaves")},
        {"feature_km", number_param(0.001, 20000, 400, "wavelength of the coarsest octave, km")}}}};
  return s;
}

class Synthesize : public CellOperator {
 public:
  const OperatorSpec& spec() const override { return spec_; }

  void run(const CellContext& ctx, CellData& data) const override {
    const json& p = *ctx.params;
    const TerrainParams params{p.at("seed").get<int64_t>(), p.at("amplitude_m").get<double>(),
                               p.at("octaves").get<int>(), p.at("feature_km").get<double>()};
    const int size = ctx.tile_size;
    const int pixel_level = ctx.cell.level() + log2_tile_size(size);
    Tile<float>& dem = data.output("dem") = Tile<float>(size, 1);
    for (int row = 0; row < size; ++row)
      for (int col = 0; col < size; ++col) {
        const FaceCoord pixel{ctx.cell.face(), global_col(ctx.cell, size, col),
                              global_row(ctx.cell, size, row)};
        const LonLat centre = pixel_centre(*ctx.grid, pixel, pixel_level);
        dem.at(col, row) = float(synthetic_elevation(up_unit(centre), params));
      }
  }

 private:
  OperatorSpec spec_ = synthesize_spec();
};

}  // namespace

std::unique_ptr<Operator> make_synthesize() { return std::make_unique<Synthesize>(); }

}  // namespace maquette::terrain
