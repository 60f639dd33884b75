// The part of a layer an export reads: its tile cells inside a region given as a lon/lat box or
// as cell ids (any levels, compacted or not).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "core/cell_id.h"
#include "core/grid.h"
#include "store/store.h"

namespace maquette {

struct RegionSpec {
  std::optional<std::array<double, 4>> bbox;  // west south east north, degrees
  std::vector<CellId> cells;                  // used when there is no bbox; none: the whole layer
};

// The region as compacted cells at `level` or coarser: a box's cells at `level` overlapping it;
// given cells (a cell finer than `level` as its ancestor at `level`); without either, the faces.
std::vector<CellId> region_cells(const Grid& grid, int level, const RegionSpec& region);

// The layer's full-resolution tile cells inside the region (cells overlapping the box; cells
// inside or holding a region cell), sorted; throws maquette::Error when there is none.
std::vector<CellId> layer_tile_cells(const Store& store, const Grid& grid, const LayerInfo& layer,
                                     const RegionSpec& region);

// The distinct ancestors at `level` (not finer than the cells), sorted.
std::vector<CellId> cells_at_level(const std::vector<CellId>& cells, int level);

}  // namespace maquette
