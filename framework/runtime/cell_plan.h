// The cells one step processes, sorted by id and split into contiguous chunks: chunks are the
// unit of parallel work, and share() gives each of several processes (MPI ranks) a disjoint
// contiguous range, so merging their results in rank order is merging in cell-id order.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "core/cell_id.h"

namespace maquette {

class CellPlan {
 public:
  CellPlan() = default;
  // `cells` must be sorted by id; chunks hold at most `chunk_size` cells.
  CellPlan(std::vector<CellId> cells, size_t chunk_size);

  const std::vector<CellId>& cells() const { return cells_; }
  size_t size() const { return cells_.size(); }
  size_t chunk_count() const { return (cells_.size() + chunk_size_ - 1) / chunk_size_; }
  // Index of the first cell of chunk `i`, and its cells.
  size_t chunk_begin(size_t i) const { return i * chunk_size_; }
  std::span<const CellId> chunk(size_t i) const;

  // The contiguous part `rank` of `ranks`, for sharing a step among MPI ranks. Rank 0's part is
  // weighted `first_weight` (> 0) against 1 for each other rank: it gets
  // ceil(cells * first_weight / (first_weight + ranks - 1)) cells (all of them when alone), the
  // others the rest, their sizes differing by at most one cell. A weight of 1 gives every part
  // the same size within one cell.
  CellPlan share(int rank, int ranks, double first_weight = 1.0) const;

 private:
  std::vector<CellId> cells_;
  size_t chunk_size_ = 1;
};

// A chunk size giving each of `threads` threads several chunks, for load balance.
size_t default_chunk_size(size_t cells, int threads);

}  // namespace maquette
