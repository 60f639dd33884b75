// Face adjacency and neighbours, checked geometrically: cells said to share an edge or a vertex
// must have coinciding corner points on the ellipsoid.
#include <gtest/gtest.h>

#include <algorithm>

#include "rhealpix/rhealpix_grid.h"
#include "test_util.h"

namespace maquette {
namespace {

const RHealpixGrid& grid() { return static_cast<const RHealpixGrid&>(default_grid()); }

// Corners in the order top-left, top-right, bottom-right, bottom-left.
std::array<LonLat, 4> corners(CellId cell) {
  std::array<LonLat, 4> out;
  const double fu[4] = {0, 1, 1, 0}, fv[4] = {0, 0, 1, 1};
  for (int i = 0; i < 4; ++i)
    out[size_t(i)] = grid().projection().from_face(cell_point(cell, fu[i], fv[i]));
  return out;
}

bool is_corner_of(LonLat p, CellId cell) {
  const auto c = corners(cell);
  return std::any_of(c.begin(), c.end(), [&](LonLat q) { return test::distance_m(p, q) < 1e-3; });
}

int shared_corners(CellId a, CellId b) {
  const auto c = corners(a);
  return int(std::count_if(c.begin(), c.end(), [&](LonLat p) { return is_corner_of(p, b); }));
}

bool at_face_corner(CellId cell) {
  const uint32_t last = (1U << cell.level()) - 1;
  return (cell.col() == 0 || cell.col() == last) && (cell.row() == 0 || cell.row() == last);
}

TEST(Neighbours, EdgeNeighboursShareTheirEdge) {
  for (int level = 0; level <= 4; ++level) {
    for (const CellId cell : test::all_cells(level)) {
      const auto c = corners(cell);
      // The edge towards neighbour i: top (TL, TR), right (TR, BR), bottom (BR, BL), left (BL, TL).
      const auto nb = grid().edge_neighbours(cell);
      for (size_t i = 0; i < 4; ++i) {
        EXPECT_NE(nb[i], cell);
        EXPECT_TRUE(is_corner_of(c[i], nb[i]) && is_corner_of(c[(i + 1) % 4], nb[i]))
            << cell.ToText() << " edge " << i << " -> " << nb[i].ToText();
        const auto back = grid().edge_neighbours(nb[i]);
        EXPECT_NE(std::find(back.begin(), back.end(), cell), back.end()) << cell.ToText();
      }
      auto sorted = std::vector<CellId>(nb.begin(), nb.end());
      std::sort(sorted.begin(), sorted.end());
      EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end()) << cell.ToText();
    }
  }
}

TEST(Neighbours, VertexNeighbours) {
  for (int level = 0; level <= 4; ++level) {
    for (const CellId cell : test::all_cells(level)) {
      const auto nb = grid().vertex_neighbours(cell);
      // Level 0: a face touches the four faces around it (its corners are cube corners).
      const size_t expected = level == 0 ? 4 : at_face_corner(cell) ? 7 : 8;
      EXPECT_EQ(nb.size(), expected) << cell.ToText();
      for (const CellId other : nb) {
        EXPECT_NE(other, cell);
        EXPECT_GE(shared_corners(cell, other), 1) << cell.ToText() << " " << other.ToText();
        const auto back = grid().vertex_neighbours(other);
        EXPECT_TRUE(std::binary_search(back.begin(), back.end(), cell)) << cell.ToText();
      }
      for (const CellId edge : grid().edge_neighbours(cell)) {
        EXPECT_TRUE(std::binary_search(nb.begin(), nb.end(), edge)) << cell.ToText();
      }
    }
  }
}

TEST(Neighbours, LevelZeroFaces) {
  // Opposite faces never touch: N-S, O-Q, P-R.
  constexpr int kOpposite[6] = {5, 3, 4, 1, 2, 0};
  for (int face = 0; face < 6; ++face) {
    for (const CellId nb : grid().edge_neighbours(CellId::FromFace(face))) {
      EXPECT_NE(nb.face(), face);
      EXPECT_NE(nb.face(), kOpposite[face]);
    }
  }
}

TEST(Wrap, InsideAndFarAway) {
  const FaceCoord inside{2, 3, 5};
  const auto same = grid().wrap(inside, 3);
  ASSERT_TRUE(same);
  EXPECT_EQ(same->face, 2);
  EXPECT_EQ(same->col, 3);
  EXPECT_EQ(same->row, 5);
  EXPECT_FALSE(grid().wrap({2, -9, 0}, 3));
  EXPECT_FALSE(grid().wrap({2, 0, 16}, 3));
  // Pixel levels beyond the cell levels.
  const int64_t n = int64_t(1) << 40;
  const auto pixel = grid().wrap({kFaceO, -1, 5}, 40);  // left of O is R's right edge
  ASSERT_TRUE(pixel);
  EXPECT_EQ(pixel->face, kFaceR);
  EXPECT_EQ(pixel->col, n - 1);
  EXPECT_EQ(pixel->row, 5);
}

TEST(Wrap, EveryCoordinateWithinAFaceWidthLandsOnAFace) {
  for (const int level : {0, 1, 2, 3}) {
    const int64_t n = int64_t(1) << level;
    for (int face = 0; face < 6; ++face) {
      for (int64_t row = -n; row < 2 * n; ++row) {
        for (int64_t col = -n; col < 2 * n; ++col) {
          const auto w = grid().wrap({face, col, row}, level);
          ASSERT_TRUE(w);
          ASSERT_TRUE(w->col >= 0 && w->col < n && w->row >= 0 && w->row < n)
              << face << " " << col << " " << row << " level " << level;
        }
      }
    }
  }
}

TEST(Wrap, CornerQuadrantsLandNearTheCorner) {
  const int level = 3;
  const int64_t n = 8;
  const double side = std::sqrt(grid().area(level));
  for (int face = 0; face < 6; ++face) {
    for (const int64_t sc : {-1, 1}) {
      for (const int64_t sr : {-1, 1}) {
        // The face corner beyond which we look, and cells a, b beyond its two edges.
        const double fu = sc < 0 ? 0 : 1, fv = sr < 0 ? 0 : 1;
        const LonLat corner = grid().projection().from_face({face, fu, fv});
        for (int64_t a = 0; a < 3; ++a) {
          for (int64_t b = 0; b < 3; ++b) {
            const int64_t col = sc < 0 ? -1 - a : n + a, row = sr < 0 ? -1 - b : n + b;
            const auto w = grid().wrap({face, col, row}, level);
            ASSERT_TRUE(w);
            ASSERT_TRUE(w->col >= 0 && w->col < n && w->row >= 0 && w->row < n);
            const CellId cell =
                CellId::FromFaceColRow(w->face, level, uint32_t(w->col), uint32_t(w->row));
            EXPECT_LT(test::distance_m(grid().centre(cell), corner), (std::max(a, b) + 2) * side)
                << face << " " << col << " " << row;
          }
        }
      }
    }
  }
}

}  // namespace
}  // namespace maquette
