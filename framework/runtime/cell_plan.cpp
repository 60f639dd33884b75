#include "runtime/cell_plan.h"

#include <algorithm>
#include <cmath>

namespace maquette {

CellPlan::CellPlan(std::vector<CellId> cells, size_t chunk_size)
    : cells_(std::move(cells)), chunk_size_(std::max<size_t>(1, chunk_size)) {}

std::span<const CellId> CellPlan::chunk(size_t i) const {
  const size_t begin = chunk_begin(i);
  return std::span<const CellId>(cells_).subspan(begin,
                                                 std::min(chunk_size_, cells_.size() - begin));
}

CellPlan CellPlan::share(int rank, int ranks, double first_weight) const {
  const size_t n = cells_.size(), r = size_t(rank), k = size_t(ranks);
  const auto part = [&](size_t begin, size_t end) {
    return CellPlan(std::vector<CellId>(cells_.begin() + long(begin), cells_.begin() + long(end)),
                    chunk_size_);
  };
  const size_t first =
      std::min(n, size_t(std::ceil(double(n) * first_weight / (first_weight + double(k - 1)))));
  if (r == 0) return part(0, first);
  // The other k - 1 ranks share the rest evenly: rank r is the (r - 1)-th of them.
  const size_t rest = n - first, i = r - 1, others = k - 1;
  const size_t begin = first + rest / others * i + std::min(i, rest % others);
  return part(begin, begin + rest / others + (i < rest % others ? 1 : 0));
}

size_t default_chunk_size(size_t cells, int threads) {
  return std::clamp<size_t>(cells / (size_t(std::max(threads, 1)) * 8), 1, 64);
}

}  // namespace maquette
