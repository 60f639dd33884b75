// texture.procedural: a surface-layer model (fitted by texture.fit or written by hand with hat
// functions) evaluated over the cells of a DEM: imagery, displaced height, normals and the
// dominant class.
#include <limits>

#include "categorical_values.h"
#include "core/error.h"
#include "field.h"
#include "model_params.h"
#include "operators.h"
#include "render.h"

namespace maquette::texture {
namespace {

OperatorSpec procedural_spec() {
  OperatorSpec s;
  s.name = "texture.procedural";
  s.description =
      "Evaluates a surface-layer model (paper 001 sections 4-5): B-spline-upsampled DEM, "
      "constraint functions, seamless noise; imagery, displaced height, normals, classes";
  s.kind = OperatorKind::Cell;
  s.inputs = {single_channel_input("dem", "elevation in metres", Semantics::Continuous)};
  for (const std::string& q : kRasterPorts)
    s.inputs.push_back({q, "raster of the model quantity '" + q + "'", true});
  s.outputs = {
      {"imagery", "synthesized colour", DType::U8, 3, Semantics::Continuous, "", 0.0},
      {"height", "DEM displaced by the layers' roughness", DType::F32, 1, Semantics::Continuous,
       "m", std::nullopt},
      {"normal", "unit normal of the displaced height (x columns, y up, z up)", DType::F32, 3,
       Semantics::Continuous, "", std::nullopt, "normal_oct"},
      {"classes", "class of the dominant layer (coverage >= 0.5)", DType::U8, 1,
       Semantics::Categorical, "", 255.0},
  };
  s.halo = kInputHalo + kPrefilterReach;  // categorical_values.h
  s.refinable = true;  // a step's "refine": levels finer than the DEM (render_tile's refine)
  s.writes_all_samples = true;  // render_tile writes every pixel, NaN where the DEM is missing
  s.params_schema = {
      {"type", "object"},
      {"additionalProperties", false},
      {"properties",
       {{"model",
         {{"type", "object"},
          {"description", "the model document (README: model JSON), e.g. a hand-authored one"}}},
        {"model_file",
         {{"type", "string"},
          {"description", "path of a model document instead, e.g. texture.fit's \"out\""}}}}}};
  s.check_params = [name = s.name](const json& params, const std::set<std::string>&) {
    check_model_params(params, name);
  };
  return s;
}

class Procedural : public CellOperator {
 public:
  const OperatorSpec& spec() const override { return spec_; }

  void run(const CellContext& ctx, CellData& data) const override {
    const std::shared_ptr<const Model> model = model_from_params(*ctx.params, spec_.name);
    std::map<std::string, const Tile<float>*> rasters;
    for (const std::string& q : kRasterPorts)
      if (data.inputs.count(q)) rasters[q] = &data.inputs.at(q);
    // Straight into the output tiles (those of the right shape reused, the others made without
    // a fill: render_tile writes every pixel).
    const int n = ctx.tile_size << ctx.refine;
    const auto target = [&](const char* port, int channels) -> float* {
      if (!data.wants(port)) return nullptr;
      Tile<float>& t = data.output(port);
      if (t.size() != n || t.channels() != channels || t.halo() != 0)
        t = Tile<float>::uninitialized(n, channels);
      return t.data().data();
    };
    render_tile(
        *model, *ctx.grid, ctx.cell, ctx.tile_size, ctx.refine, data.input("dem"), rasters,
        spec_.name,
        {target("imagery", 3), target("height", 1), target("normal", 3), target("classes", 1)});
  }

 private:
  OperatorSpec spec_ = procedural_spec();
};

}  // namespace

std::unique_ptr<Operator> make_procedural() { return std::make_unique<Procedural>(); }

}  // namespace maquette::texture
