// CellId encoding, text ids and ranges.
#include "core/cell_id.h"

#include <gtest/gtest.h>

#include "core/error.h"

namespace maquette {
namespace {

TEST(CellId, TextRoundTrip) {
  for (const char* text : {"N", "S", "Q2013", "R33330021", "O00000000000000000000000000000",
                           "S33333333333333333333333333333"}) {
    const auto cell = CellId::FromText(text);
    ASSERT_TRUE(cell) << text;
    EXPECT_TRUE(cell->is_valid());
    EXPECT_EQ(cell->ToText(), text);
    EXPECT_EQ(CellId::Parse(text), *cell);
    EXPECT_EQ(CellId::Parse(std::to_string(cell->id())), *cell);
  }
}

TEST(CellId, RejectsMalformed) {
  for (const char* text :
       {"", "X", "n", "Q4", "Q20a", "Q 1", "Q-1", "O000000000000000000000000000000"}) {
    EXPECT_FALSE(CellId::FromText(text)) << text;
    EXPECT_THROW(CellId::Parse(text), Error) << text;
  }
  EXPECT_THROW(CellId::Parse("0"), Error);
  EXPECT_THROW(CellId::Parse("-5"), Error);
  EXPECT_THROW(CellId::Parse(std::to_string(uint64_t(6) << 59 | 1ULL << 58)), Error);  // face 6
  EXPECT_THROW(CellId::Parse("99999999999999999999999"), Error);
  EXPECT_THROW(CellId(0).ToText(), Error);
}

TEST(CellId, Encoding) {
  const CellId q = CellId::FromFaceColRow(3, 4, 0b0101, 0b1001);
  EXPECT_EQ(q.ToText(), "Q2103");  // digits 2*row_bit + col_bit, from the top bit down
  EXPECT_EQ(q.face(), 3);
  EXPECT_EQ(q.level(), 4);
  EXPECT_EQ(q.col(), 0b0101U);
  EXPECT_EQ(q.row(), 0b1001U);
  EXPECT_EQ(q.parent().ToText(), "Q210");
  EXPECT_EQ(q.parent(1).ToText(), "Q2");
  EXPECT_EQ(q.child(2).ToText(), "Q21032");
  EXPECT_LT(CellId::FromFace(5).range_max().id(), uint64_t(1) << 62);
  const CellId leaf = CellId::FromFaceColRow(5, 29, (1U << 29) - 1, 12345);
  EXPECT_EQ(leaf.col(), (1U << 29) - 1);
  EXPECT_EQ(leaf.row(), 12345U);
  EXPECT_TRUE(leaf.is_leaf());
}

TEST(CellId, DescendantRangesAreContiguousAndDisjoint) {
  for (const char* text : {"N", "Q2", "R3301", "S0123012301230123012301230123"}) {
    const CellId cell = *CellId::FromText(text);
    EXPECT_EQ(cell.child(0).range_min(), cell.range_min());
    EXPECT_EQ(cell.child(3).range_max(), cell.range_max());
    for (int d = 0; d < 3; ++d) {
      EXPECT_EQ(cell.child(d).range_max().id() + 2, cell.child(d + 1).range_min().id());
      EXPECT_LT(cell.child(d), cell.child(d + 1));
      EXPECT_TRUE(cell.contains(cell.child(d)));
      EXPECT_FALSE(cell.child(d).contains(cell.child(d + 1)));
    }
  }
  // Faces follow each other too.
  for (int f = 0; f + 1 < CellId::kNumFaces; ++f) {
    EXPECT_EQ(CellId::FromFace(f).range_max().id() + 2, CellId::FromFace(f + 1).range_min().id());
  }
}

}  // namespace
}  // namespace maquette
