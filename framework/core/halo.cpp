#include "core/halo.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"

namespace maquette {
namespace {

// Where one halo pixel is read from: a tile-local pixel of a (neighbouring) cell.
struct HaloSource {
  int col, row;          // destination, tile-local (halo coordinates)
  CellId cell;           // source cell at the tile's level
  int src_col, src_row;  // pixel inside the source tile
};

void check_tile(const Tile<float>& tile, CellId cell, int size) {
  if (tile.size() != size || tile.halo() != 0)
    throw Error("halo: tile of cell " + cell.ToText() + " has size " + std::to_string(tile.size()) +
                " (halo " + std::to_string(tile.halo()) + "), expected " + std::to_string(size));
}

}  // namespace

std::optional<FaceCoord> pixel_source(const Grid& grid, CellId cell, int size, int col, int row) {
  const int pixel_level = cell.level() + log2_tile_size(size);
  const FaceCoord c{cell.face(), global_col(cell, size, col), global_row(cell, size, row)};
  const int64_t n = int64_t(1) << pixel_level;
  if (c.col >= 0 && c.col < n && c.row >= 0 && c.row < n) return c;
  return grid.wrap(c, pixel_level);
}

LonLat pixel_centre(const Grid& grid, FaceCoord pixel, int pixel_level) {
  return face_point_lonlat(grid, pixel.face, double(pixel.col), double(pixel.row), pixel_level);
}

LonLat face_point_lonlat(const Grid& grid, int face, double col, double row, int pixel_level) {
  const PlaneSquare square = grid.plane_square(CellId::FromFace(face));
  const double scale = std::ldexp(1.0, -pixel_level);
  const double u = (col + 0.5) * scale, v = (row + 0.5) * scale;
  return grid.inverse({square.x_min + u * square.side, square.y_max - v * square.side});
}

Tile<float> assemble_halo(const Grid& grid, CellId cell, int size, int halo,
                          const TileFetch& fetch) {
  std::deque<std::optional<Tile<float>>> kept;  // the fetched tiles, at stable places
  return assemble_halo(grid, cell, size, halo, [&](CellId c) -> const Tile<float>* {
    const auto& tile = kept.emplace_back(fetch(c));
    return tile ? &*tile : nullptr;
  });
}

Tile<float> assemble_halo(const Grid& grid, CellId cell, int size, int halo, const TileFind& find) {
  const int log2_size = log2_tile_size(size);
  if (halo < 0 || halo > size)
    throw Error("halo: " + std::to_string(halo) + " pixels around a tile of " +
                std::to_string(size) + " (must be in [0, size])");

  // First find every halo pixel's source, so each neighbour tile is fetched once (at most 8).
  std::vector<HaloSource> sources;
  std::vector<std::pair<CellId, const Tile<float>*>> tiles{{cell, find(cell)}};
  const auto cached = [&](CellId c) -> const Tile<float>* {
    for (const auto& [id, tile] : tiles)
      if (id == c) return tile;
    return tiles.emplace_back(c, find(c)).second;
  };
  const int mask = size - 1;
  for (int row = -halo; row < size + halo; ++row) {
    for (int col = -halo; col < size + halo; ++col) {
      if (col >= 0 && col < size && row >= 0 && row < size) continue;
      const std::optional<FaceCoord> src = pixel_source(grid, cell, size, col, row);
      if (!src) continue;
      const CellId source_cell =
          CellId::FromFaceColRow(src->face, cell.level(), uint32_t(src->col >> log2_size),
                                 uint32_t(src->row >> log2_size));
      sources.push_back({col, row, source_cell, int(src->col & mask), int(src->row & mask)});
      cached(source_cell);
    }
  }

  int channels = 0;
  for (const auto& [id, tile] : tiles) {
    if (!tile) continue;
    check_tile(*tile, id, size);
    if (channels == 0) channels = tile->channels();
    if (tile->channels() != channels)
      throw Error("halo: tile of cell " + id.ToText() + " has " + std::to_string(tile->channels()) +
                  " channels, expected " + std::to_string(channels));
  }

  Tile<float> out(size, channels == 0 ? 1 : channels, halo,
                  std::numeric_limits<float>::quiet_NaN());
  if (const Tile<float>* own = tiles.front().second)
    for (int row = 0; row < size; ++row)  // a row's samples and channels at once
      std::copy_n(&own->at(0, row), size_t(size) * size_t(channels), &out.at(0, row));
  for (const HaloSource& s : sources)
    if (const Tile<float>* tile = cached(s.cell))
      for (int k = 0; k < channels; ++k)
        out.at(s.col, s.row, k) = tile->at(s.src_col, s.src_row, k);
  return out;
}

Tile<float> sample_field(const Grid& grid, CellId cell, int size,
                         const std::function<double(LonLat)>& field) {
  const int level = cell.level() + log2_tile_size(size);
  Tile<float> tile(size, 1);
  for (int row = 0; row < size; ++row)
    for (int col = 0; col < size; ++col)
      tile.at(col, row) = float(field(pixel_centre(
          grid, {cell.face(), global_col(cell, size, col), global_row(cell, size, row)}, level)));
  return tile;
}

}  // namespace maquette
