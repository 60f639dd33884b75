#include "stored_layers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <vector>

namespace maquette::test {

Tile<float> float_tile(const Store& store, const std::string& layer, CellId cell) {
  const LayerInfo info = store.require_layer(layer);
  const auto raw = store.get_tile(layer, cell);
  if (!raw) return Tile<float>(info.tile_size, info.channels, 0, NAN);
  return to_tile<float>(*raw, info.nodata ? &*info.nodata : nullptr);
}

std::vector<CellId> differing_tiles(const Store& a, const Store& b, const std::string& layer) {
  const std::vector<CellId> in_a = a.tile_cells(layer), in_b = b.tile_cells(layer);
  std::set<CellId> cells(in_a.begin(), in_a.end());
  cells.insert(in_b.begin(), in_b.end());
  std::vector<CellId> differ;
  for (const CellId cell : cells) {
    const auto tile_a = a.get_tile(layer, cell), tile_b = b.get_tile(layer, cell);
    if (!tile_a || !tile_b || tile_a->bytes != tile_b->bytes) differ.push_back(cell);
  }
  return differ;
}

size_t expect_same_tiles(const Store& a, const Store& b, const std::string& layer) {
  for (const CellId cell : differing_tiles(a, b, layer))
    ADD_FAILURE() << layer << ", cell " << cell.ToText() << ": not the same tile in both stores";
  return a.tile_cells(layer).size();
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
