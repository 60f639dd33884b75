#include "image/layer_cells.h"

#include <algorithm>

#include "core/error.h"
#include "core/region.h"

namespace maquette {

std::vector<CellId> region_cells(const Grid& grid, int level, const RegionSpec& region) {
  std::vector<CellId> wanted = region.cells;
  if (region.bbox) {
    const auto& b = *region.bbox;
    wanted = grid.cover_bbox(b[0], b[1], b[2], b[3], level, Containment::Overlap);
  } else if (wanted.empty()) {
    for (int face = 0; face < grid.num_faces(); ++face) wanted.push_back(CellId::FromFace(face));
  }
  // A region cell finer than the layer lies in the tile of its ancestor at the layer's level.
  for (CellId& c : wanted)
    if (c.level() > level) c = c.parent(level);
  return compact(std::move(wanted));
}

std::vector<CellId> layer_tile_cells(const Store& store, const Grid& grid, const LayerInfo& layer,
                                     const RegionSpec& region) {
  std::vector<CellId> tiles;
  for (CellId c : region_cells(grid, layer.level, region)) {
    const auto found = store.tile_cells(layer.name, c.range_min(), c.range_max());
    tiles.insert(tiles.end(), found.begin(), found.end());
  }
  if (tiles.empty())
    throw Error("layer '" + layer.name + "' in " + store.path() + " has no tiles in the region");
  std::sort(tiles.begin(), tiles.end());
  return tiles;
}

std::vector<CellId> cells_at_level(const std::vector<CellId>& cells, int level) {
  std::vector<CellId> out;
  out.reserve(cells.size());
  for (CellId c : cells) out.push_back(c.parent(level));
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace maquette
