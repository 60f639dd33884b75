// Test stores with known values: a cell's tile filled from a function of where each sample lies,
// blocks of cells to fill, and the layer description such a store needs.
#pragma once

#include <cstring>
#include <string>
#include <vector>

#include "core/grid.h"
#include "core/tile.h"
#include "store/store.h"

namespace maquette::test {

// Where one sample of a cell's tile lies.
struct TileSample {
  PlanePoint plane;  // the pixel centre on the rHEALPix plane
  LonLat lonlat;     // the same point on the ellipsoid
  int64_t col = 0;   // face pixel at the tile's pixel level (global_col, global_row)
  int64_t row = 0;
};

// The samples of `cell`'s size x size tile, row-major from the top-left.
std::vector<TileSample> tile_samples(const Grid& grid, CellId cell, int size);

// `cell`'s size x size tile of `channels` channels; channel k of sample s holds T(value(s, k)).
template <typename T, typename F>
RawTile make_tile(const Grid& grid, CellId cell, int size, int channels, F value) {
  std::vector<T> v;
  v.reserve(size_t(size) * size_t(size) * size_t(channels));
  for (const TileSample& s : tile_samples(grid, cell, size))
    for (int k = 0; k < channels; ++k) v.push_back(T(value(s, k)));
  RawTile t{dtype_of<T>(), size, channels, std::vector<std::byte>(v.size() * sizeof(T))};
  std::memcpy(t.bytes.data(), v.data(), t.bytes.size());
  return t;
}

// The 2 x 2 block of cells at `level` under the parent of the cell holding `p`.
std::vector<CellId> block_of_four(const Grid& grid, LonLat p, int level);

// A raster layer `name` of `channels` channels of `dtype`, tiles of `tile_size` at `level`; the
// other fields at their defaults (no nodata, continuous, no units).
LayerInfo layer_info(const std::string& name, DType dtype, int channels, int tile_size, int level);

}  // namespace maquette::test
