#include "ingest_fixture.h"

#include "core/halo.h"
#include "core/tile.h"
#include "stored_layers.h"

namespace maquette::test {

std::unique_ptr<Store> ingest(const std::string& dir, const std::string& name,
                              const std::vector<std::string>& sources, RasterIngestOptions o) {
  const std::string path = dir + "/" + name + ".mqt";
  o.quiet = true;
  ingest_raster(path, sources, o);
  return Store::open(path, Store::Mode::ReadOnly);
}

void for_each_sample(const Store& store, const std::string& layer,
                     const std::function<void(CellId, LonLat, const float*)>& visit) {
  const Grid& grid = default_grid();
  const LayerInfo info = store.require_layer(layer);
  const int n = info.tile_size, pixel_level = info.level + log2_tile_size(n);
  for (CellId cell : store.tile_cells(layer)) {
    const Tile<float> tile = float_tile(store, layer, cell);
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c) {
        const LonLat p = pixel_centre(
            grid, {cell.face(), global_col(cell, n, c), global_row(cell, n, r)}, pixel_level);
        visit(cell, p, &tile.at(c, r, 0));
      }
  }
}

}  // namespace maquette::test
