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

void StreamCompactor::add(CellId cell) {
  // Held cells may still merge only if this cell starts where the last one's next sibling does.
  const bool continues = !held_.empty() && cell.range_min() == held_.back().next().range_min();
  if (!continues) finish();
  if (!continues && (cell.is_face() || cell.parent().range_min() != cell.range_min()))
    return emit_(cell);  // not the first of its siblings: never merged
  held_.push_back(cell);
  // Four complete siblings are the last four held, in digit order.
  while (held_.size() >= 4 && !held_.back().is_face()) {
    const CellId parent = held_.back().parent();
    const auto first = held_.end() - 4;
    bool complete = true;
    for (int d = 0; d < 4; ++d) complete = complete && first[d] == parent.child(d);
    if (!complete) break;
    held_.erase(first, held_.end());
    held_.push_back(parent);
  }
  if (held_.back().is_face()) finish();
}

void StreamCompactor::finish() {
  for (const CellId cell : held_) emit_(cell);
  held_.clear();
}

std::vector<CellId> compact(std::vector<CellId> cells) {
  std::vector<CellId> out;
  StreamCompactor compactor([&out](CellId cell) { out.push_back(cell); });
  for (const CellId cell : normalize(std::move(cells))) compactor.add(cell);
  compactor.finish();
  return out;
}

std::vector<CellId> uncompact(std::span<const CellId> cells, int level) {
  CellId::CheckLevel(level);
  std::vector<CellId> coarse;
  coarse.reserve(cells.size());
  for (const CellId cell : cells)
    coarse.push_back(cell.level() > level ? cell.parent(level) : cell);
  std::vector<CellId> out;
  for (const CellId cell : normalize(std::move(coarse)))
    for_each_at_level(cell, level, [&out](CellId c) { out.push_back(c); });
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
