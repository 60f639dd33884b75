// terrain.fill_voids: DEM voids filled by a PDE solved per void (void_fill.h) when the void lies,
// with its boundary, inside the halo of every tile it touches, and through the input's overview
// pyramid (pyramid_fill.h) when it is larger; seamless across tiles either way.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/error.h"
#include "core/halo.h"
#include "operators.h"
#include "pyramid_fill.h"
#include "runtime/params_schema.h"
#include "void_fill.h"

namespace maquette::terrain {
namespace {

// The largest void solved exactly is kHalo - 1 pixels: a void that reaches the tile then lies in
// the window with the two rings of samples the biharmonic stencil reads around it.
constexpr int kHalo = 64;
static_assert(kPyramidSweeps + 1 <= kHalo && kPyramidHalo <= kHalo);

OperatorSpec fill_voids_spec() {
  OperatorSpec s;
  s.name = "terrain.fill_voids";
  s.description =
      "Fills DEM voids (NaN/nodata) of any size smoothly from their borders: the Laplace or "
      "biharmonic equation solved per void up to 63 pixels, a multigrid membrane through the "
      "input's overview pyramid beyond; seamless across tiles";
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
           "voids of up to 63 pixels: biharmonic (thin plate, smooth (C1) across the void's "
           "border) or laplace (membrane, stays within the border's range); larger voids: "
           "membrane"}}},
        {"pyramid",
         {{"type", "string"},
          {"default", ""},
          {"description",
           "the layer the input 'dem' reads: voids larger than 63 pixels are filled through its "
           "overview pyramid in the run's store (required when there are such voids)"}}}}}};
  return s;
}

class FillVoids : public CellOperator {
 public:
  const OperatorSpec& spec() const override { return spec_; }

  void run(const CellContext& ctx, CellData& data) const override {
    const Tile<float>& dem = data.input("dem");
    const int size = ctx.tile_size;
    if (dem.halo() < kHalo || dem.size() != size)
      throw Error("terrain.fill_voids: input 'dem' of cell " + ctx.cell.ToText() +
                  " needs a halo of " + std::to_string(kHalo) + " pixels and tile size " +
                  std::to_string(size));
    const FillMethod method =
        ctx.params->at("method") == "laplace" ? FillMethod::Laplace : FillMethod::Biharmonic;
    Tile<float> filled = fill_voids(dem, {method, kHalo - 1}).interior();
    if (std::any_of(filled.data().begin(), filled.data().end(),
                    [](float v) { return std::isnan(v); })) {
      const Tile<float> large = fill_through_pyramid(dem, ctx.cell, pyramid(ctx, dem));
      for (int row = 0; row < size; ++row)
        for (int col = 0; col < size; ++col)
          if (std::isnan(filled.at(col, row))) filled.at(col, row) = large.at(col, row);
    }

    if (data.wants("filled")) {
      Tile<float>& mask = data.output("filled") = Tile<float>(size, 1);
      for (int row = 0; row < size; ++row)
        for (int col = 0; col < size; ++col)
          mask.at(col, row) =
              std::isnan(dem.at(col, row)) && !std::isnan(filled.at(col, row)) ? 1.f : 0.f;
    }
    if (data.wants("dem")) data.output("dem") = std::move(filled);
  }

 private:
  // The overview tiles around the cell of params.pyramid, once it is checked to be the input's
  // layer: same level and tile size, and the same samples at the cell.
  static PyramidFetch pyramid(const CellContext& ctx, const Tile<float>& dem) {
    const std::string name = ctx.params->at("pyramid");
    const std::string where = "terrain.fill_voids: cell " + ctx.cell.ToText();
    if (name.empty())
      throw Error(where +
                  " has voids larger than 63 pixels, which are filled from the overviews of the "
                  "input layer: set params.pyramid to the layer of input 'dem'");
    if (!ctx.store) throw Error(where + ": params.pyramid needs the run's store");
    const LayerInfo layer = ctx.store->require_layer(name);
    const std::optional<RawTile> raw = ctx.store->get_tile(name, ctx.cell);
    const std::optional<double> nodata = layer.nodata;
    if (layer.level != ctx.cell.level() || layer.tile_size != ctx.tile_size || !raw ||
        !same_samples(to_tile<float>(*raw, nodata ? &*nodata : nullptr), dem))
      throw Error(where + ": params.pyramid: layer '" + name +
                  "' is not the layer of input 'dem' (its tile differs)");
    return [&ctx, name, nodata](int levels_up, int halo) {
      const CellId ancestor = ctx.cell.parent(ctx.cell.level() - levels_up);
      return assemble_halo(*ctx.grid, ancestor, ctx.tile_size, halo,
                           [&](CellId c) -> std::optional<Tile<float>> {
                             const std::optional<RawTile> tile = ctx.store->get_overview(name, c);
                             if (!tile) return std::nullopt;
                             return to_tile<float>(*tile, nodata ? &*nodata : nullptr);
                           });
    };
  }

  // Same bits at every sample of `tile` and the interior of `window` (NaN equal to NaN).
  static bool same_samples(const Tile<float>& tile, const Tile<float>& window) {
    for (int row = 0; row < tile.size(); ++row)
      for (int col = 0; col < tile.size(); ++col) {
        const float a = tile.at(col, row), b = window.at(col, row);
        if (std::isnan(a) ? !std::isnan(b) : std::memcmp(&a, &b, sizeof a) != 0) return false;
      }
    return true;
  }

  OperatorSpec spec_ = fill_voids_spec();
};

}  // namespace

std::unique_ptr<Operator> make_fill_voids() { return std::make_unique<FillVoids>(); }

}  // namespace maquette::terrain
