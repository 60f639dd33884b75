#include "runtime/cell_plan.h"

#include <algorithm>

namespace maquette {

CellPlan::CellPlan(std::vector<CellId> cells, size_t chunk_size)
    : cells_(std::move(cells)), chunk_size_(std::max<size_t>(1, chunk_size)) {}

std::span<const CellId> CellPlan::chunk(size_t i) const {
  const size_t begin = chunk_begin(i);
  return std::span<const CellId>(cells_).subspan(begin,
                                                 std::min(chunk_size_, cells_.size() - begin));
}

CellPlan CellPlan::share(int rank, int ranks) const {
  const size_t n = cells_.size(), r = size_t(rank), k = size_t(ranks);
  const size_t begin = n / k * r + std::min(r, n % k);
  const size_t end = begin + n / k + (r < n % k ? 1 : 0);
  return CellPlan(std::vector<CellId>(cells_.begin() + long(begin), cells_.begin() + long(end)),
                  chunk_size_);
}

size_t default_chunk_size(size_t cells, int threads) {
  return std::clamp<size_t>(cells / (size_t(std::max(threads, 1)) * 8), 1, 64);
}

}  // namespace maquette
