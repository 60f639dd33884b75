// The faces unfolded around an anchor (core/unfolded_faces.h): the neighbour strips equal the
// grid's own wrap on every pixel, to_anchor inverts from_anchor, the unturned N-O strip and the
// turned N-P strip lie where PROJ's rhealpix puts the plane points (the P square turned about
// the corner it shares with N), a placed tile's pixels lie at its place, and across every seam of
// every anchor neighbouring samples are as far apart on the ellipsoid (GeographicLib) as neighbours
// within a face.
#include "core/unfolded_faces.h"

#include <gtest/gtest.h>
#include <proj.h>

#include <GeographicLib/Geodesic.hpp>
#include <array>
#include <cmath>

#include "core/halo.h"
#include "test_util.h"

namespace maquette {
namespace {

constexpr int kLevel = 4;  // 16 pixels a face side
constexpr int64_t kN = int64_t(1) << kLevel;

// Every pixel of the anchor's 3 x 3 face neighbourhood: the edge strips are the grid's wrap
// and invert, the corner quadrants are gaps.
void expect_strips_wrap(const Grid& grid, int anchor, int level) {
  const int64_t n = int64_t(1) << level;
  const UnfoldedFaces plane(grid, anchor, level);
  int placed = 0;
  for (int face = 0; face < CellId::kNumFaces; ++face) placed += plane.places(face);
  EXPECT_EQ(placed, 5) << anchor;  // itself and its four edge neighbours, not the opposite face
  for (int64_t row = -n; row < 2 * n; ++row)
    for (int64_t col = -n; col < 2 * n; ++col) {
      const auto p = plane.from_anchor(col, row);
      const bool inside_col = col >= 0 && col < n, inside_row = row >= 0 && row < n;
      if (!inside_col && !inside_row) {  // the corner gaps
        EXPECT_FALSE(p) << anchor << " " << level << " " << col << " " << row;
        continue;
      }
      ASSERT_TRUE(p) << anchor << " " << level << " " << col << " " << row;
      const auto wrapped = grid.wrap({anchor, col, row}, level);
      ASSERT_TRUE(wrapped);
      EXPECT_EQ(p->face, wrapped->face);
      EXPECT_EQ(p->col, wrapped->col) << anchor << " " << level << " " << col << " " << row;
      EXPECT_EQ(p->row, wrapped->row) << anchor << " " << level << " " << col << " " << row;
      const auto back = plane.to_anchor(*p);
      ASSERT_TRUE(back);
      EXPECT_EQ(back->col, col);
      EXPECT_EQ(back->row, row);
    }
  EXPECT_FALSE(plane.from_anchor(2 * n, 0));
  EXPECT_FALSE(plane.from_anchor(0, -n - 1));
}

TEST(UnfoldedFaces, StripsAreTheGridsWrapAndInvert) {
  const Grid& grid = default_grid();
  for (const int level : {0, 1, kLevel})
    for (int anchor = 0; anchor < CellId::kNumFaces; ++anchor)
      expect_strips_wrap(grid, anchor, level);
  EXPECT_TRUE(UnfoldedFaces::adjacent(grid, 0, 1));   // N, O
  EXPECT_FALSE(UnfoldedFaces::adjacent(grid, 0, 5));  // N, S
  EXPECT_FALSE(UnfoldedFaces::adjacent(grid, 1, 3));  // O, Q
}

// Every placed tile's pixel (c, r) at TilePlace::at(c, r) is the cell's own pixel there, read
// back with from_anchor, and tile_pixel() inverts at().
TEST(UnfoldedFaces, APlacedTilesPixelsLieAtItsPlaceAndInvert) {
  const Grid& grid = default_grid();
  constexpr int kSize = 4, kCellLevel = kLevel - 2;
  for (int anchor = 0; anchor < CellId::kNumFaces; ++anchor) {
    const UnfoldedFaces plane(grid, anchor, kLevel);
    for (int face = 0; face < CellId::kNumFaces; ++face) {
      if (!plane.places(face)) continue;
      for (const auto& [col, row] : {std::array<uint32_t, 2>{0, 0}, {3, 1}, {2, 3}}) {
        const CellId cell = CellId::FromFaceColRow(face, kCellLevel, col, row);
        const auto place = plane.place_tile(cell, kSize);
        ASSERT_TRUE(place) << cell.ToText();
        for (int r = 0; r < kSize; ++r)
          for (int c = 0; c < kSize; ++c) {
            const auto q = place->at(c, r);
            const auto p = plane.from_anchor(q[0], q[1]);
            ASSERT_TRUE(p) << anchor << " " << cell.ToText();
            EXPECT_EQ((std::array<int64_t, 3>{p->face, p->col, p->row}),
                      (std::array<int64_t, 3>{face, col * kSize + c, row * kSize + r}))
                << anchor << " " << cell.ToText() << " " << c << " " << r;
            EXPECT_EQ(place->tile_pixel(q), (std::array<int64_t, 2>{c, r}));
          }
      }
    }
  }
}

// Anchor N: the strip below it is O's plane as PROJ lays it (N sits above O); the strip right of
// it is P's square turned by 90 degrees about N's bottom-right corner, where N, O and P meet; so
// are points between pixel centres there (fractional from_anchor, face_point_lonlat).
TEST(UnfoldedFaces, NeighbourStripsLieWherePROJPutsThem) {
  const Grid& grid = default_grid();
  PJ_CONTEXT* ctx = proj_context_create();
  PJ* pj = proj_create(ctx, "+proj=rhealpix +ellps=WGS84 +north_square=0 +south_square=0");
  ASSERT_NE(pj, nullptr);
  const auto proj_inverse = [&](double x, double y) {
    const PJ_COORD c = proj_trans(pj, PJ_INV, proj_coord(x, y, 0, 0));
    return LonLat{c.lp.lam * 180 / M_PI, c.lp.phi * 180 / M_PI};
  };
  const PlaneSquare n_face = grid.plane_square(CellId::FromFace(0));
  const double pixel = n_face.side / double(kN);
  const double corner_x = n_face.x_min + n_face.side, corner_y = n_face.y_max - n_face.side;
  const UnfoldedFaces plane(grid, 0, kLevel);
  double worst_m = 0;
  for (int64_t i = 0; i < kN; ++i)
    for (int64_t depth = 0; depth < kN; ++depth) {
      // Below N: anchor-frame (i, kN + depth), the plane point straight down.
      const LonLat below = pixel_centre(grid, *plane.from_anchor(i, kN + depth), kLevel);
      EXPECT_EQ(plane.from_anchor(i, kN + depth)->face, 1);
      const LonLat below_proj = proj_inverse(n_face.x_min + (double(i) + 0.5) * pixel,
                                             n_face.y_max - (double(kN + depth) + 0.5) * pixel);
      // Right of N: anchor-frame (kN + depth, i), the plane point (dx, dy) from the corner turned
      // clockwise by 90 degrees to (dy, -dx), into P's square.
      const LonLat right = pixel_centre(grid, *plane.from_anchor(kN + depth, i), kLevel);
      EXPECT_EQ(plane.from_anchor(kN + depth, i)->face, 2);
      const double dx = (double(depth) + 0.5) * pixel;
      const double dy = n_face.side - (double(i) + 0.5) * pixel;
      const LonLat right_proj = proj_inverse(corner_x + dy, corner_y - dx);
      // A point between pixel centres (a corner's neighbourhood, as a lake's shore corners):
      // anchor-frame (kN + depth + 0.25, i - 0.3), read on P through a pixel around it.
      const auto at = plane.from_anchor(double(kN + depth) + 0.25, double(i) - 0.3);
      ASSERT_TRUE(at);
      EXPECT_EQ(at->face, 2);
      const LonLat between = face_point_lonlat(grid, at->face, at->col, at->row, kLevel);
      const LonLat between_proj = proj_inverse(corner_x + n_face.side - (double(i) + 0.2) * pixel,
                                               corner_y - (double(depth) + 0.75) * pixel);
      worst_m =
          std::max({worst_m, test::distance_m(below, below_proj),
                    test::distance_m(right, right_proj), test::distance_m(between, between_proj)});
      if (depth > 0) continue;
      // Points within half a pixel of a pixel of another face: 0.3 pixel past N's right edge
      // (on P), and 0.2 pixel inside N's top edge (on N).
      const auto past = plane.from_anchor(double(kN) - 0.2, double(i));
      const auto inside = plane.from_anchor(double(i), -0.3);
      ASSERT_TRUE(past && inside);
      EXPECT_EQ(past->face, 2);
      EXPECT_EQ(inside->face, 0);
      const LonLat past_proj =
          proj_inverse(corner_x + n_face.side - (double(i) + 0.5) * pixel, corner_y - 0.3 * pixel);
      const LonLat inside_proj =
          proj_inverse(n_face.x_min + (double(i) + 0.5) * pixel, n_face.y_max - 0.2 * pixel);
      worst_m = std::max(
          {worst_m,
           test::distance_m(face_point_lonlat(grid, past->face, past->col, past->row, kLevel),
                            past_proj),
           test::distance_m(face_point_lonlat(grid, inside->face, inside->col, inside->row, kLevel),
                            inside_proj)});
    }
  proj_destroy(pj);
  proj_context_destroy(ctx);
  EXPECT_LT(worst_m, 0.01);  // PROJ's inverse solves the authalic latitude to ~2e-8 degrees
}

// Across each seam of each anchor, the geodesic distance between anchor-frame neighbours (one
// pixel each side of the edge) is within 0.7..1.4 of that between the neighbours one pixel
// inside on either side: a wrong turn or offset would put them up to a face width apart.
TEST(UnfoldedFaces, NeighboursAcrossEverySeamAreNeighboursOnTheEllipsoid) {
  const Grid& grid = default_grid();
  const GeographicLib::Geodesic& wgs84 = GeographicLib::Geodesic::WGS84();
  const auto metres = [&](const UnfoldedFaces& plane, int64_t c0, int64_t r0, int64_t c1,
                          int64_t r1) {
    const LonLat a = pixel_centre(grid, *plane.from_anchor(c0, r0), kLevel);
    const LonLat b = pixel_centre(grid, *plane.from_anchor(c1, r1), kLevel);
    double s = 0;
    wgs84.Inverse(a.lat, a.lon, b.lat, b.lon, s);
    return s;
  };
  double lowest = 10, highest = 0;
  for (int anchor = 0; anchor < CellId::kNumFaces; ++anchor) {
    const UnfoldedFaces plane(grid, anchor, kLevel);
    for (int64_t i = 0; i < kN; ++i) {
      // (col, row) one step outward and the step itself, for the four edges.
      const std::array<std::array<int64_t, 4>, 4> seams = {
          {{i, 0, 0, -1}, {kN - 1, i, 1, 0}, {i, kN - 1, 0, 1}, {0, i, -1, 0}}};
      for (const auto& [c, r, dc, dr] : seams) {
        const double across = metres(plane, c, r, c + dc, r + dr);
        const double inside = metres(plane, c - dc, r - dr, c, r);
        const double beyond = metres(plane, c + dc, r + dr, c + 2 * dc, r + 2 * dr);
        const double ratio = across / (0.5 * (inside + beyond));
        lowest = std::min(lowest, ratio);
        highest = std::max(highest, ratio);
      }
    }
  }
  EXPECT_GT(lowest, 0.7);
  EXPECT_LT(highest, 1.4);
  RecordProperty("seam_ratio_range", std::to_string(lowest) + ".." + std::to_string(highest));
}

}  // namespace
}  // namespace maquette
