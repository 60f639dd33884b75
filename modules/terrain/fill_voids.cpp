// terrain.fill_voids: DEM voids filled by a PDE solved per void (void_fill.h) when the void lies,
// with its boundary, inside the halo of every tile it touches, and through the input's overview
// pyramid (pyramid_fill.h) when it is larger; seamless across tiles either way.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/data_footprint.h"
#include "core/error.h"
#include "core/halo.h"
#include "operators.h"
#include "pyramid_fill.h"
#include "runtime/input_halo.h"
#include "runtime/params_schema.h"
#include "store/downsample.h"
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
  s.inputs = {single_channel_input("dem", "elevation with voids as nodata", Semantics::Continuous)};
  s.outputs = {
      {"dem", "elevation with voids filled", DType::F32, 1, Semantics::Continuous, "m",
       std::nullopt},
      {"filled", "1 where a void was filled, else 0", DType::U8, 1, Semantics::Categorical, "",
       std::nullopt},
  };
  s.halo = kHalo;
  s.fills_footprint = true;
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
         named_param(NamedKind::Layer, "",
                     "the layer the input 'dem' reads: voids larger than 63 pixels are filled "
                     "through its overview pyramid in the run's store (required when there are "
                     "such voids)")}}}};
  return s;
}

class FillVoids : public CellOperator {
 public:
  const OperatorSpec& spec() const override { return spec_; }

  void run(const CellContext& ctx, CellData& data) const override {
    const Tile<float>& dem = input_with_halo("terrain.fill_voids", ctx, data, "dem", kHalo);
    const int size = ctx.tile_size;
    const FillMethod method =
        ctx.params->at("method") == "laplace" ? FillMethod::Laplace : FillMethod::Biharmonic;
    Tile<float> filled = fill_voids(dem, {method, kHalo - 1}).interior();
    if (std::any_of(filled.data().begin(), filled.data().end(),
                    [](float v) { return std::isnan(v); })) {
      const Pyramid p = pyramid(ctx, dem);
      const FootprintTest inside = footprint_test(ctx, p.footprint);
      if (!inside || left_inside(filled, inside)) {
        const Tile<float> large = fill_through_pyramid(dem, ctx.cell, p.fetch, inside);
        for (int row = 0; row < size; ++row)
          for (int col = 0; col < size; ++col)
            if (std::isnan(filled.at(col, row))) filled.at(col, row) = large.at(col, row);
      }
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
  struct Pyramid {
    PyramidFetch fetch;
    std::optional<DataFootprint> footprint;  // of the layer's sources, if it records one
  };

  // The overview tiles around the cell of params.pyramid and its footprint, once it is checked to
  // be the input's layer: same level and tile size, and the same samples at the cell (all NaN
  // where it has no tile: a cell within the footprint, OperatorSpec::fills_footprint).
  static Pyramid pyramid(const CellContext& ctx, const Tile<float>& dem) {
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
    if (layer.level != ctx.cell.level() || layer.tile_size != ctx.tile_size ||
        !same_samples(raw ? to_tile<float>(*raw, nodata ? &*nodata : nullptr)
                          : Tile<float>(ctx.tile_size, 1, 0, NAN),
                      dem))
      throw Error(where + ": params.pyramid: layer '" + name +
                  "' is not the layer of input 'dem' (its tile differs)");
    PyramidFetch fetch = [&ctx, layer](int levels_up, int halo) {
      const PyramidTile t = pyramid_tile(ctx.cell, ctx.tile_size, levels_up);
      const int halvings = std::max(0, levels_up - ctx.cell.level());
      return assemble_halo(
          *ctx.grid, t.cell, t.size, halo, [&](CellId c) -> std::optional<Tile<float>> {
            std::optional<RawTile> tile = c.level() == layer.level
                                              ? ctx.store->get_tile(layer.name, c)
                                              : ctx.store->get_overview(layer.name, c);
            if (!tile) return std::nullopt;
            for (int i = 0; i < halvings; ++i) tile = halved(*tile, layer);
            return to_tile<float>(*tile, layer.nodata ? &*layer.nodata : nullptr);
          });
    };
    return {std::move(fetch), DataFootprint::from_provenance(layer.provenance, name)};
  }

  // A face's tile at half resolution, by the store's own overview rule (so the same bits as the
  // overview a tiling of smaller tiles keeps for that level).
  static RawTile halved(const RawTile& tile, LayerInfo layer) {
    layer.tile_size = tile.size;
    const RawTile quadrants = build_overview({&tile, nullptr, nullptr, nullptr}, layer);
    RawTile out{tile.dtype, tile.size / 2, tile.channels, {}};
    const size_t row_bytes = size_t(out.size) * tile.channels * dtype_size(tile.dtype);
    for (int row = 0; row < out.size; ++row) {
      const auto first = quadrants.bytes.begin() + ptrdiff_t(row * 2 * row_bytes);
      out.bytes.insert(out.bytes.end(), first, first + ptrdiff_t(row_bytes));
    }
    return out;
  }

  // Whether a pixel of a pyramid level lies in the footprint (empty without a footprint).
  static FootprintTest footprint_test(const CellContext& ctx,
                                      const std::optional<DataFootprint>& footprint) {
    if (!footprint) return {};
    return [&ctx, &footprint](int levels_up, int col, int row) {
      const PyramidTile t = pyramid_tile(ctx.cell, ctx.tile_size, levels_up);
      const std::optional<FaceCoord> pixel = pixel_source(*ctx.grid, t.cell, t.size, col, row);
      return pixel && footprint->contains(
                          pixel_centre(*ctx.grid, *pixel, t.cell.level() + log2_tile_size(t.size)));
    };
  }

  // Whether a NaN sample of `tile` lies inside the footprint.
  static bool left_inside(const Tile<float>& tile, const FootprintTest& inside) {
    for (int row = 0; row < tile.size(); ++row)
      for (int col = 0; col < tile.size(); ++col)
        if (std::isnan(tile.at(col, row)) && inside(0, col, row)) return true;
    return false;
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
