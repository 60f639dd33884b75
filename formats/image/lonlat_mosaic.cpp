#include "image/lonlat_mosaic.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

#include "core/error.h"
#include "core/lonlat_bounds.h"

namespace maquette {
namespace {

constexpr double kMetresPerDegree = 111319.49;  // at the equator, to pick a pixel size

// Crops the raster to the rows and columns holding data: cells are often much larger than the
// data in them.
void crop_to_data(LonLatRaster& r) {
  int c0 = r.width, c1 = -1, r0 = r.height, r1 = -1;
  for (int row = 0; row < r.height; ++row)
    for (int col = 0; col < r.width; ++col)
      if (std::isfinite(r.at(col, row))) {
        c0 = std::min(c0, col), c1 = std::max(c1, col);
        r0 = std::min(r0, row), r1 = std::max(r1, row);
      }
  if (c1 < 0) return;  // no data at all: keep the frame
  std::vector<float> values;
  values.reserve(size_t(c1 - c0 + 1) * size_t(r1 - r0 + 1) * size_t(r.channels));
  for (int row = r0; row <= r1; ++row)
    for (int col = c0; col <= c1; ++col)
      for (int k = 0; k < r.channels; ++k) values.push_back(r.at(col, row, k));
  r.west += c0 * r.step;
  r.north -= r0 * r.step;
  r.width = c1 - c0 + 1;
  r.height = r1 - r0 + 1;
  r.values = std::move(values);
}

}  // namespace

LonLatRaster mosaic_layer(const Store& store, const Grid& grid, const std::string& layer,
                          std::vector<CellId> cells, int max_side) {
  const LayerInfo info = store.require_layer(layer);
  if (cells.empty()) cells = store.tile_cells(layer);
  std::sort(cells.begin(), cells.end());
  if (cells.empty()) throw Error("layer '" + layer + "' in " + store.path() + " has no tiles");
  const LonLatBounds b = lonlat_bounds(grid, cells);

  // The layer's own pixel size, coarsened (through overviews) until the raster fits max_side.
  const int log2n = log2_tile_size(info.tile_size);
  double step = grid.level_info(info.level, info.tile_size).pixel_m / kMetresPerDegree;
  int level = info.level;
  while (level > 0 && std::max(b.east - b.west, b.north - b.south) / step > max_side) {
    --level;
    step *= 2;
  }
  LonLatRaster r;
  r.west = b.west;
  r.north = b.north;
  r.step = step;
  r.width = std::max(1, int(std::ceil((b.east - b.west) / step)));
  r.height = std::max(1, int(std::ceil((b.north - b.south) / step)));
  r.channels = info.channels;
  r.values.assign(size_t(r.width) * size_t(r.height) * size_t(r.channels),
                  std::numeric_limits<float>::quiet_NaN());

  const double* nodata = info.nodata ? &*info.nodata : nullptr;
  const int pixel_level = std::min(level + log2n, CellId::kMaxLevel);
  const int shift = pixel_level - level;  // tile pixels per cell side = 2^shift
  std::map<CellId, std::optional<Tile<float>>> tiles;
  std::vector<LonLat> points(size_t(r.width));
  std::vector<CellId> ids(points.size());
  for (int row = 0; row < r.height; ++row) {
    for (int col = 0; col < r.width; ++col)
      points[size_t(col)] = {std::remainder(r.west + (col + 0.5) * step, 360.0),
                             r.north - (row + 0.5) * step};
    grid.cells_from_points(points, pixel_level, ids);
    for (int col = 0; col < r.width; ++col) {
      const CellId pixel = ids[size_t(col)];
      const CellId cell = pixel.parent(level);
      if (level == info.level && !std::binary_search(cells.begin(), cells.end(), cell)) continue;
      auto [it, fresh] = tiles.try_emplace(cell);
      if (fresh) {
        const auto raw =
            level == info.level ? store.get_tile(layer, cell) : store.get_overview(layer, cell);
        if (raw) it->second = to_tile<float>(*raw, nodata);
      }
      if (!it->second) continue;
      // With a tile coarser than 2^shift pixels (tile sizes above 2^(29 - level)) pixels repeat.
      const int scale = info.tile_size >> shift;
      const int tc = int(pixel.col() - (cell.col() << shift)) * scale;
      const int tr = int(pixel.row() - (cell.row() << shift)) * scale;
      for (int k = 0; k < r.channels; ++k)
        r.values[(size_t(row) * size_t(r.width) + size_t(col)) * size_t(r.channels) + size_t(k)] =
            it->second->at(tc, tr, k);
    }
  }
  crop_to_data(r);
  return r;
}

}  // namespace maquette
