#include "stored_layers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace maquette::test {

Tile<float> float_tile(const Store& store, const std::string& layer, CellId cell) {
  const LayerInfo info = store.require_layer(layer);
  const auto raw = store.get_tile(layer, cell);
  if (!raw) return Tile<float>(info.tile_size, info.channels, 0, NAN);
  return to_tile<float>(*raw, info.nodata ? &*info.nodata : nullptr);
}

size_t expect_same_tiles(const Store& a, const Store& b, const std::string& layer) {
  const std::vector<CellId> cells = a.tile_cells(layer);
  EXPECT_EQ(cells, b.tile_cells(layer)) << layer;
  for (const CellId cell : cells) {
    const auto in_a = a.get_tile(layer, cell), in_b = b.get_tile(layer, cell);
    EXPECT_TRUE(in_a && in_b && in_a->bytes == in_b->bytes) << layer << ", cell " << cell.ToText();
  }
  return cells.size();
}

size_t expect_same_content(const Store& a, const Store& b, const std::string& layer) {
  const std::vector<CellId> cells = a.content_cells(layer);
  EXPECT_EQ(cells, b.content_cells(layer)) << layer;
  for (const CellId cell : cells)
    EXPECT_EQ(a.get_content(layer, cell), b.get_content(layer, cell))
        << layer << ", cell " << cell.ToText();
  return cells.size();
}

}  // namespace maquette::test
