#include "gltf/terrain_source.h"

#include <algorithm>

#include "core/error.h"
#include "core/halo.h"

namespace maquette {

LayerInfo require_texture_layer(const Store& store, const std::string& name) {
  const LayerInfo info = store.require_layer(name);
  if (info.kind != LayerKind::Raster || info.dtype != DType::U8 || info.channels == 2 ||
      info.channels > 4)
    throw Error("--texture layer '" + name +
                "' is not imagery: expected a uint8 raster of 1, 3 "
                "or 4 channels, found " +
                std::string(layer_kind_name(info.kind)) + " " +
                std::string(dtype_name(info.dtype)) + " with " + std::to_string(info.channels) +
                " channel(s)");
  return info;
}

std::optional<RawTile> tile_at_level(const Store& store, const LayerInfo& layer, CellId cell) {
  if (cell.level() > layer.level)
    throw Error("level " + std::to_string(cell.level()) + " is finer than layer '" + layer.name +
                "' (level " + std::to_string(layer.level) + ")");
  return cell.level() == layer.level ? store.get_tile(layer.name, cell)
                                     : store.get_overview(layer.name, cell);
}

std::optional<Tile<float>> dem_with_halo(const Store& store, const Grid& grid, const LayerInfo& dem,
                                         CellId cell) {
  const double* nodata = dem.nodata ? &*dem.nodata : nullptr;
  auto fetch = [&](CellId c) -> std::optional<Tile<float>> {
    const auto raw = tile_at_level(store, dem, c);
    if (!raw) return std::nullopt;
    return to_tile<float>(*raw, nodata);
  };
  const auto centre = fetch(cell);
  if (!centre) return std::nullopt;
  return assemble_halo(grid, cell, dem.tile_size, 2,
                       [&](CellId c) { return c == cell ? centre : fetch(c); });
}

std::optional<Tile<uint8_t>> texture_of(const Store& store, const LayerInfo& imagery, CellId cell) {
  const CellId source = cell.level() > imagery.level ? cell.parent(imagery.level) : cell;
  const auto raw = tile_at_level(store, imagery, source);
  if (!raw) return std::nullopt;
  const Tile<uint8_t> tile = to_tile<uint8_t>(*raw);
  if (source == cell) return tile;
  // The cell's square within its ancestor's tile (at least one pixel).
  const int depth = cell.level() - source.level();
  const int size = std::max(1, tile.size() >> depth);
  const int64_t col = int64_t(cell.col() - (source.col() << depth)) * tile.size() >> depth;
  const int64_t row = int64_t(cell.row() - (source.row() << depth)) * tile.size() >> depth;
  Tile<uint8_t> out(size, tile.channels());
  for (int r = 0; r < size; ++r)
    for (int c = 0; c < size; ++c)
      for (int k = 0; k < tile.channels(); ++k)
        out.at(c, r, k) = tile.at(int(col) + c, int(row) + r, k);
  return out;
}

}  // namespace maquette
