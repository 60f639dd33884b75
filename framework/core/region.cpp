#include "core/region.h"

#include <algorithm>
#include <string>

namespace maquette {

std::vector<CellId> normalize(std::vector<CellId> cells) {
  // By range start, the larger of two cells starting together first: a cell is then covered
  // exactly when its range ends no later than the last kept one.
  std::sort(cells.begin(), cells.end(), [](CellId a, CellId b) {
    return a.range_min() != b.range_min() ? a.range_min() < b.range_min()
                                          : a.range_max() > b.range_max();
  });
  std::vector<CellId> out;
  for (const CellId cell : cells) {
    if (!out.empty() && cell.range_max() <= out.back().range_max()) continue;
    out.push_back(cell);
  }
  return out;
}

std::vector<CellId> compact(std::vector<CellId> cells) {
  std::vector<CellId> out;
  for (const CellId cell : normalize(std::move(cells))) {
    out.push_back(cell);
    // Sorted disjoint cells: four complete siblings are the last four pushed, in digit order.
    while (out.size() >= 4 && !out.back().is_face()) {
      const CellId parent = out.back().parent();
      const auto first = out.end() - 4;
      bool complete = true;
      for (int d = 0; d < 4; ++d) complete = complete && first[d] == parent.child(d);
      if (!complete) break;
      out.erase(first, out.end());
      out.push_back(parent);
    }
  }
  return out;
}

std::vector<CellId> uncompact(std::span<const CellId> cells, int level) {
  CellId::CheckLevel(level);
  std::vector<CellId> coarse;
  coarse.reserve(cells.size());
  for (const CellId cell : cells)
    coarse.push_back(cell.level() > level ? cell.parent(level) : cell);
  std::vector<CellId> out;
  for (const CellId cell : normalize(std::move(coarse))) {
    const CellId end = cell.range_max().parent(level).next();
    for (CellId c = cell.range_min().parent(level); c != end; c = c.next()) out.push_back(c);
  }
  return out;
}

std::vector<IdRange> to_ranges(std::span<const CellId> normalized) {
  std::vector<IdRange> out;
  for (const CellId cell : normalized) {
    // Leaf ids are odd (the sentinel is bit 0), so consecutive leaves differ by 2.
    if (!out.empty() && out.back().max.id() + 2 == cell.range_min().id()) {
      out.back().max = cell.range_max();
    } else {
      out.push_back({cell.range_min(), cell.range_max()});
    }
  }
  return out;
}

bool contains(std::span<const CellId> normalized, CellId cell) {
  const auto it = std::upper_bound(normalized.begin(), normalized.end(), cell.range_min(),
                                   [](CellId a, CellId b) { return a < b.range_min(); });
  return it != normalized.begin() && std::prev(it)->contains(cell);
}

}  // namespace maquette
