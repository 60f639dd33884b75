#include "runtime/cell_plan.h"

#include <gtest/gtest.h>

namespace maquette {
namespace {

std::vector<CellId> cells(int n) {
  std::vector<CellId> out;
  for (CellId c = CellId::FromFaceColRow(3, 3, 0, 0); int(out.size()) < n; c = c.next())
    out.push_back(c);
  return out;
}

TEST(CellPlan, ChunksAreContiguousAndCoverAllCells) {
  const CellPlan plan(cells(10), 4);
  ASSERT_EQ(plan.chunk_count(), 3u);
  std::vector<CellId> seen;
  for (size_t i = 0; i < plan.chunk_count(); ++i) {
    EXPECT_EQ(plan.chunk_begin(i), seen.size());
    for (const CellId c : plan.chunk(i)) seen.push_back(c);
  }
  EXPECT_EQ(seen, plan.cells());
  EXPECT_EQ(plan.chunk(2).size(), 2u);
}

TEST(CellPlan, SharesAreDisjointContiguousAndInOrder) {
  const CellPlan plan(cells(11), 2);
  std::vector<CellId> joined;
  for (int rank = 0; rank < 3; ++rank) {
    const CellPlan share = plan.share(rank, 3);
    EXPECT_GE(share.size(), 3u);
    EXPECT_LE(share.size(), 4u);
    joined.insert(joined.end(), share.cells().begin(), share.cells().end());
  }
  EXPECT_EQ(joined, plan.cells());
  EXPECT_EQ(plan.share(4, 20).size(), 1u);
  EXPECT_EQ(plan.share(15, 20).size(), 0u);
}

// Rank 0 weighted 0.8 against 1: ceil(256 * 0.8 / 1.8) = 114 of 256 cells, the other 142; with
// 3 ranks ceil(256 * 0.8 / 2.8) = 74, the other two 91 each. Contiguous and in order either way.
TEST(CellPlan, WeightedFirstShareIsSmaller) {
  const CellPlan plan(cells(256), 1);
  for (const auto& [ranks, sizes] : std::vector<std::pair<int, std::vector<size_t>>>{
           {1, {256}}, {2, {114, 142}}, {3, {74, 91, 91}}}) {
    std::vector<CellId> joined;
    for (int rank = 0; rank < ranks; ++rank) {
      const CellPlan share = plan.share(rank, ranks, 0.8);
      EXPECT_EQ(share.size(), sizes[size_t(rank)]) << rank << " of " << ranks;
      joined.insert(joined.end(), share.cells().begin(), share.cells().end());
    }
    EXPECT_EQ(joined, plan.cells());
  }
  // Fewer cells than ranks: rank 0 still gets its rounded-up part, the others what is left.
  const CellPlan few(cells(2), 1);
  EXPECT_EQ(few.share(0, 3, 0.8).size(), 1u);
  EXPECT_EQ(few.share(1, 3, 0.8).size(), 1u);
  EXPECT_EQ(few.share(2, 3, 0.8).size(), 0u);
}

TEST(CellPlan, DefaultChunkSizeBalancesThreads) {
  EXPECT_EQ(default_chunk_size(0, 4), 1u);
  EXPECT_EQ(default_chunk_size(320, 4), 10u);
  EXPECT_EQ(default_chunk_size(1000000, 4), 64u);
}

}  // namespace
}  // namespace maquette
