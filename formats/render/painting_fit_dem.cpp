#include "render/painting_fit_dem.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <exception>

#include "core/enu_frame.h"
#include "core/error.h"
#include "image/layer_sampler.h"

namespace maquette {
namespace {

// The provenance key of a warped DEM: what made it (and marks an unfinished one as ours).
constexpr const char* kWarpedBy = "warped_by";

// The distance (metres) from `cell`'s centre to its farthest corner, and a sample more: a disc
// about the centre holding every sample of its tile.
double tile_radius(const Grid& grid, CellId cell, int tile_size) {
  const LonLat c = grid.centre(cell);
  const EnuFrame frame({c.lon, c.lat, 0});
  double radius = 0;
  for (const LonLat& p : grid.boundary(cell, 1)) {
    const auto q = frame.to_enu(p.lon, p.lat);
    radius = std::max(radius, std::hypot(q[0], q[1]));
  }
  return radius + grid.level_info(cell.level(), tile_size).pixel_m;
}

// `cell`'s tile moved by the warp: each sample's own bytes where the warp leaves it in place, the
// DEM read bilinearly at its source elsewhere.
RawTile warped_tile(const Grid& grid, const LayerInfo& dem, CellId cell, const RawTile& raw,
                    const GroundWarp& warp, LayerSampler& sampler) {
  const double* nodata = dem.nodata ? &*dem.nodata : nullptr;
  Tile<double> tile = to_tile<double>(raw, nodata);
  const PlaneSquare square = grid.plane_square(cell);
  const int n = dem.tile_size;
  for (int row = 0; row < n; ++row)
    for (int col = 0; col < n; ++col) {
      const LonLat p = grid.inverse({square.x_min + (col + 0.5) / n * square.side,
                                     square.y_max - (row + 0.5) / n * square.side});
      const LonLat s = warp.source(p);
      if (s.lon == p.lon && s.lat == p.lat) continue;
      float h = NAN;
      if (!sampler.sample(s, grid.cell_from_point(s, dem.level), &h)) h = NAN;
      // Without a nodata value a missing height would be stored as a number (0 m in an integer
      // DEM, a pit dug to the datum): the sample keeps its own height instead.
      if (std::isnan(h) && !nodata) continue;
      tile.at(col, row) = h;
    }
  return from_tile(tile, dem.dtype, nodata);
}

void write_tiles(Store& store, const Grid& grid, const LayerInfo& dem, const GroundWarp& warp,
                 const std::string& out, int64_t run) {
  LayerSampler sampler(store, grid, dem, dem.level, LayerSampler::Read::kBilinear);
  const std::vector<CellId> cells = store.tile_cells(dem.name);
  constexpr size_t kTilesPerBatch = 16;  // a commit costs about as much as a tile's work
  for (size_t begin = 0; begin < cells.size(); begin += kTilesPerBatch) {
    Store::Batch batch(store);
    for (size_t i = begin; i < std::min(cells.size(), begin + kTilesPerBatch); ++i) {
      const CellId cell = cells[i];
      const auto raw = store.get_tile(dem.name, cell);
      if (!raw) throw Error("tile " + cell.ToText() + " of '" + dem.name + "' vanished");
      const bool still = warp.still_near(grid.centre(cell), tile_radius(grid, cell, dem.tile_size));
      batch.put_tile(out, cell, still ? *raw : warped_tile(grid, dem, cell, *raw, warp, sampler));
      batch.mark_done(run, 0, cell);
      sampler.forget_unused();
    }
    batch.commit();
  }
  store.update_overviews(out);
}

}  // namespace

void check_warped_dem_name(const Store& store, const std::string& name) {
  if (name.empty()) throw Error("--warped-dem: the layer's name is empty");
  const auto layer = store.layer(name);
  const bool unfinished = layer && store.incomplete(name) && layer->provenance.contains(kWarpedBy);
  if (layer && !unfinished)
    throw Error("--warped-dem layer '" + name + "' already exists in " + store.path() +
                ": the warped DEM is written as a new layer, nothing stored is replaced");
}

void write_warped_dem(Store& store, const Grid& grid, const LayerInfo& dem, const GroundWarp& warp,
                      const std::string& out, const nlohmann::json& warped_by) {
  LayerInfo layer = dem;
  layer.name = out;
  layer.provenance = {{kWarpedBy, warped_by}};
  // Heights made from heights: the same vertical datum and sources' footprint.
  for (const char* key : {"vertical_datum", "footprint"})
    if (dem.provenance.contains(key)) layer.provenance[key] = dem.provenance[key];
  // A warped DEM an interrupted run left (check_warped_dem_name) is dropped whole first: its
  // tiles may be of another DEM or other clicks, and the new run writes only its own cells.
  if (store.layer(out))
    store.drop_layer(out, store.begin_run({{"render fit --warped-dem: drop the unfinished", out}}));
  const int64_t run = store.begin_run({{"render fit --warped-dem", warped_by}});
  try {
    store.create_layer(layer);
    store.mark_incomplete(out, run);
    write_tiles(store, grid, dem, warp, out, run);
    store.finish_run(run, "ok");
  } catch (const std::exception& e) {
    try {
      store.drop_layer(out, run);
    } catch (const std::exception& undo) {
      spdlog::warn("{}: could not drop the unfinished layer '{}': {}", store.path(), out,
                   undo.what());
    }
    throw Error("--warped-dem layer '" + out + "' not written: " + e.what());
  }
}

}  // namespace maquette
