// terrain.fill_voids: DEM voids filled by a PDE solved per void (void_fill.h), seamless across
// tiles because every void it fills lies, with its boundary, inside the halo of every tile it
// touches.
#include <cmath>

#include "core/error.h"
#include "operators.h"
#include "runtime/params_schema.h"
#include "void_fill.h"

namespace maquette::terrain {
namespace {

// The largest void filled is kHalo - 1 pixels: a void that reaches the tile then lies in the
// window with the two rings of samples the biharmonic stencil reads around it.
constexpr int kHalo = 64;

OperatorSpec fill_voids_spec() {
  OperatorSpec s;
  s.name = "terrain.fill_voids";
  s.description =
      "Fills DEM voids (NaN/nodata) smoothly from their borders by solving the Laplace or "
      "biharmonic equation per void; seamless across tiles";
  s.kind = OperatorKind::Cell;
  s.inputs = {{"dem", "elevation with voids as nodata", false}};
  s.outputs = {
      {"dem", "elevation with voids filled", DType::F32, 1, Semantics::Continuous, "m",
       std::nullopt},
      {"filled", "1 where a void was filled, else 0", DType::U8, 1, Semantics::Categorical, "",
       std::nullopt},
  };
  s.halo = kHalo;
  s.params_schema = {
      {"type", "object"},
      {"additionalProperties", false},
      {"properties",
       {{"method",
         {{"type", "string"},
          {"enum", {"biharmonic", "laplace"}},
          {"default", "biharmonic"},
          {"description",
           "biharmonic: thin plate, smooth (C1) across the void's border; laplace: membrane, "
           "stays within the border's range"}}},
        {"max_void_px",
         integer_param(1, kHalo - 1, kHalo - 1,
                       "largest void filled, pixels along its bounding box's longer side; larger "
                       "voids stay nodata")}}}};
  return s;
}

class FillVoids : public CellOperator {
 public:
  const OperatorSpec& spec() const override { return spec_; }

  void run(const CellContext& ctx, CellData& data) const override {
    const Tile<float>& dem = data.input("dem");
    const int size = ctx.tile_size;
    const json& params = *ctx.params;
    const FillOptions options{
        params.at("method") == "laplace" ? FillMethod::Laplace : FillMethod::Biharmonic,
        params.at("max_void_px").get<int>()};
    // Below this halo a void touching the tile could be cut by the window's edge.
    if (dem.halo() < options.max_void_px + 1 || dem.size() != size)
      throw Error("terrain.fill_voids: input 'dem' of cell " + ctx.cell.ToText() +
                  " needs a halo of " + std::to_string(options.max_void_px + 1) +
                  " pixels and tile size " + std::to_string(size));

    const Tile<float> filled = fill_voids(dem, options);
    Tile<float>* out_dem = data.wants("dem") ? &data.output("dem") : nullptr;
    Tile<float>* out_mask = data.wants("filled") ? &data.output("filled") : nullptr;
    if (out_dem) *out_dem = filled.interior();
    if (out_mask) {
      *out_mask = Tile<float>(size, 1);
      for (int row = 0; row < size; ++row)
        for (int col = 0; col < size; ++col)
          out_mask->at(col, row) =
              std::isnan(dem.at(col, row)) && !std::isnan(filled.at(col, row)) ? 1.f : 0.f;
    }
  }

 private:
  OperatorSpec spec_ = fill_voids_spec();
};

}  // namespace

std::unique_ptr<Operator> make_fill_voids() { return std::make_unique<FillVoids>(); }

}  // namespace maquette::terrain
