// Grid-agnostic helpers on regions given as vectors of CellId. A normalized region is sorted by
// id, without duplicates and without a cell contained in another; its cells are disjoint, so id
// order equals the order of their descendant ranges.
#pragma once

#include <span>
#include <vector>

#include "core/cell_id.h"

namespace maquette {

// A closed range of leaf-level ids [min, max], for range scans over stored cells.
struct IdRange {
  CellId min;
  CellId max;
  friend bool operator==(const IdRange&, const IdRange&) = default;
};

// Sorts, removes duplicates and cells contained in another cell of the region.
std::vector<CellId> normalize(std::vector<CellId> cells);
// Normalizes, then replaces every 4 complete siblings by their parent, recursively.
std::vector<CellId> compact(std::vector<CellId> cells);
// The cells of the region at `level`, sorted: coarser cells are replaced by their descendants,
// finer cells by their ancestor at `level` (which covers them). Throws for a bad level.
std::vector<CellId> uncompact(std::span<const CellId> cells, int level);
// The descendant ranges of a normalized region, adjacent ranges merged.
std::vector<IdRange> to_ranges(std::span<const CellId> normalized);
// Whether `cell` lies inside a cell of a normalized region.
bool contains(std::span<const CellId> normalized, CellId cell);

}  // namespace maquette
