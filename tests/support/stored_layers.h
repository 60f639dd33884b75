// Reading a test store's layers back: a cell's float tile with the layer's nodata as NaN, and the
// same layer of two stores compared to the bit (same inputs, other thread counts or ranks).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/cell_id.h"
#include "core/tile.h"
#include "store/store.h"

namespace maquette::test {

// `cell`'s tile of `layer` as floats, the layer's nodata (if any) as NaN; a tile of NaN of the
// layer's tile size (and channels) where the store holds none. Throws maquette::Error for a layer
// the store does not have.
Tile<float> float_tile(const Store& store, const std::string& layer, CellId cell);

// The cells of raster layer `layer` whose tiles' bytes differ between `a` and `b`, or that only
// one of them holds, in order (no test failure: a test may expect some).
std::vector<CellId> differing_tiles(const Store& a, const Store& b, const std::string& layer);

// Test failures (gtest) unless `a` and `b` hold tiles of raster layer `layer` in the same cells,
// with the same bytes (one per differing_tiles cell); the number of cells of `a`.
size_t expect_same_tiles(const Store& a, const Store& b, const std::string& layer);
// The same for the content blobs of content layer `layer`.
size_t expect_same_content(const Store& a, const Store& b, const std::string& layer);

}  // namespace maquette::test
