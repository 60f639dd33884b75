// Region helpers: normalize, compact, uncompact, ranges, contains.
#include "core/region.h"

#include <gtest/gtest.h>

#include "core/error.h"

namespace maquette {
namespace {

CellId id(const char* text) { return *CellId::FromText(text); }

TEST(Region, Normalize) {
  const auto out = normalize({id("Q21"), id("Q2"), id("N3"), id("Q2"), id("N"), id("R0")});
  EXPECT_EQ(out, (std::vector<CellId>{id("N"), id("Q2"), id("R0")}));
}

TEST(Region, CompactIsRecursive) {
  std::vector<CellId> cells;
  for (int d = 0; d < 4; ++d) cells.push_back(id("Q10").child(d));
  for (const char* t : {"Q11", "Q12", "Q13", "Q0", "Q2", "Q3", "R1"}) cells.push_back(id(t));
  EXPECT_EQ(compact(cells), (std::vector<CellId>{id("Q"), id("R1")}));
  EXPECT_EQ(compact({id("Q0"), id("Q1"), id("Q3")}),
            (std::vector<CellId>{id("Q0"), id("Q1"), id("Q3")}));
  // Six faces are not siblings.
  std::vector<CellId> faces;
  for (int f = 0; f < 6; ++f) faces.push_back(CellId::FromFace(f));
  EXPECT_EQ(compact(faces), faces);
}

TEST(Region, UncompactRoundTrip) {
  const std::vector<CellId> region = {id("N"), id("Q21"), id("R0123")};
  const auto fine = uncompact(region, 4);
  EXPECT_EQ(fine.size(), 256U + 16U + 1U);
  EXPECT_TRUE(std::is_sorted(fine.begin(), fine.end()));
  EXPECT_EQ(compact(fine), region);
  EXPECT_EQ(uncompact(region, 1),
            (std::vector<CellId>{id("N0"), id("N1"), id("N2"), id("N3"), id("Q2"), id("R0")}));
  EXPECT_THROW(uncompact(region, 30), Error);
}

TEST(Region, RangesAndContains) {
  const std::vector<CellId> region = normalize({id("Q0"), id("Q1"), id("Q3"), id("R20")});
  const auto ranges = to_ranges(region);
  ASSERT_EQ(ranges.size(), 3U);
  EXPECT_EQ(ranges[0], (IdRange{id("Q0").range_min(), id("Q1").range_max()}));
  EXPECT_EQ(ranges[1], (IdRange{id("Q3").range_min(), id("Q3").range_max()}));
  EXPECT_TRUE(contains(region, id("Q1032")));
  EXPECT_TRUE(contains(region, id("Q0")));
  EXPECT_TRUE(contains(region, id("R2013")));
  EXPECT_FALSE(contains(region, id("Q2")));
  EXPECT_FALSE(contains(region, id("Q")));
  EXPECT_FALSE(contains(region, id("N")));
  EXPECT_FALSE(contains(region, id("R21")));
}

}  // namespace
}  // namespace maquette
