// `maquette cells cover` streams its cells: a cover of millions of cells is listed under a memory
// cap far below what holding it takes, each cell once and in id order, and --compact gives the
// same region in its fewest cells, computed as the cells come.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "core/cell_id.h"
#include "run_cli.h"

namespace maquette::test {
namespace {

// The program's address space at start is some 180 MB (its libraries); listing the globe at level
// 10 as JSON held the cells and their JSON array, about 1 GB.
const std::string kCap = "prlimit --as=400000000";

std::vector<CellId> lines_to_cells(const std::string& text) {
  std::vector<CellId> cells;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) cells.push_back(CellId::Parse(line));
  return cells;
}

TEST(CellsCover, TheGlobeAtLevel10StreamsUnderAMemoryCap) {
  if (const std::string why = address_space_cap_unavailable(); !why.empty()) GTEST_SKIP() << why;
  const CliResult r =
      run_maquette_under(kCap, "cells cover --bbox -180 -90 180 90 --level 10 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // ["N0000000000","N0000000001",...,"S3333333333"]: every cell of the level (6 x 4^10), each
  // once, in id order.
  ASSERT_TRUE(r.out.starts_with("[\"") && r.out.ends_with("\"]\n")) << r.out.substr(0, 100);
  constexpr int64_t kCells = int64_t(6) << 20;
  int64_t count = 0;
  CellId previous;
  bool ordered = true;
  for (size_t at = 2; at < r.out.size(); at += 14, ++count) {
    const CellId cell = CellId::Parse(r.out.substr(at, 11));
    ordered = ordered && cell.level() == 10 && (count == 0 || previous < cell);
    previous = cell;
  }
  EXPECT_EQ(count, kCells);
  EXPECT_TRUE(ordered);
  EXPECT_EQ(r.out.size(), size_t(kCells) * 14 + 2);
}

TEST(CellsCover, CompactIsComputedAsTheCellsCome) {
  if (const std::string why = address_space_cap_unavailable(); !why.empty()) GTEST_SKIP() << why;
  // 25 million cells at level 11, compacted to the six faces.
  const CliResult globe =
      run_maquette_under(kCap, "cells cover --bbox -180 -90 180 90 --level 11 --compact");
  ASSERT_EQ(globe.exit_code, 0) << globe.err;
  EXPECT_EQ(globe.out, "N\nO\nP\nQ\nR\nS\n");

  // A box across the antimeridian and a polar face: the compact cover holds exactly the plain
  // cover's cells, and no four complete siblings.
  for (const std::string box : {"170 50 -160 80", "-30 -10 40 35"}) {
    const CliResult plain = run_maquette("cells cover --level 8 --bbox " + box);
    const CliResult compact = run_maquette("cells cover --level 8 --compact --bbox " + box);
    ASSERT_EQ(plain.exit_code, 0) << plain.err;
    ASSERT_EQ(compact.exit_code, 0) << compact.err;
    const std::vector<CellId> cells = lines_to_cells(plain.out);
    const std::vector<CellId> coarse = lines_to_cells(compact.out);
    EXPECT_LT(coarse.size(), cells.size() / 4) << box;
    std::vector<CellId> expanded;
    std::set<CellId> parents;
    for (size_t i = 0; i < coarse.size(); ++i) {
      if (i > 0) {
        EXPECT_LT(coarse[i - 1].range_max(), coarse[i].range_min()) << box;
      }
      const CellId end = coarse[i].range_max().parent(8).next();
      for (CellId c = coarse[i].range_min().parent(8); c != end; c = c.next())
        expanded.push_back(c);
      if (!coarse[i].is_face()) parents.insert(coarse[i].parent());
    }
    EXPECT_EQ(expanded, cells) << box;
    for (const CellId parent : parents) {
      int children = 0;
      for (const CellId c : coarse)
        children += c.level() == parent.level() + 1 && parent.contains(c);
      EXPECT_LT(children, 4) << box << ": the four children of " << parent.ToText();
    }
  }
}

}  // namespace
}  // namespace maquette::test
