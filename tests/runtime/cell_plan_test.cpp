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

TEST(CellPlan, DefaultChunkSizeBalancesThreads) {
  EXPECT_EQ(default_chunk_size(0, 4), 1u);
  EXPECT_EQ(default_chunk_size(320, 4), 10u);
  EXPECT_EQ(default_chunk_size(1000000, 4), 64u);
}

}  // namespace
}  // namespace maquette
