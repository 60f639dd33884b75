// Grid-agnostic helpers on regions given as vectors of CellId. A normalized region is sorted by
// id, without duplicates and without a cell contained in another; its cells are disjoint, so id
// order equals the order of their descendant ranges.
#pragma once

#include <functional>
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
// Calls `visit` on every cell at `level` in `cell` (of `level` or coarser), in id order.
template <class Visit>
void for_each_at_level(CellId cell, int level, Visit&& visit) {
  const CellId end = cell.range_max().parent(level).next();
  for (CellId c = cell.range_min().parent(level); c != end; c = c.next()) visit(c);
}

// compact() of a normalized region given cell by cell in id order, without holding it: each
// compacted cell is passed on as soon as no later cell can complete its siblings (at most three
// cells of each level are held).
class StreamCompactor {
 public:
  explicit StreamCompactor(std::function<void(CellId)> emit) : emit_(std::move(emit)) {}
  void add(CellId cell);
  void finish();  // passes on the cells held

 private:
  std::vector<CellId> held_;  // incomplete runs of siblings from digit 0, each inside the next
                              // sibling of the run before it
  std::function<void(CellId)> emit_;
};

// The descendant ranges of a normalized region, adjacent ranges merged.
std::vector<IdRange> to_ranges(std::span<const CellId> normalized);
// Whether `cell` lies inside a cell of a normalized region.
bool contains(std::span<const CellId> normalized, CellId cell);

}  // namespace maquette
