// Seamless across rHEALPix face edges (issue 18): the faces' plane (core/face_plane.h) lays the
// faces where the grid's table says and where the store's halo puts a neighbour's pixels; then
// synthesis.transfer's cells on both sides of the edge between O and P (longitude -90), of the
// antimeridian (R's right edge, O's left) and of N's edge with O, and a cell of another tiling,
// against one synthesis of a window across the edge computed here in the plane laid by hand (O P
// Q R left to right, the row's columns modulo its width, N above O): the same sources, pixel for
// pixel. A small synthetic painting and a land cover that is a function of longitude and
// latitude. A column period that would break each level's parity is refused.
#include <gtest/gtest.h>

#include <array>

#include "../synthesis.h"
#include "../transfer_exemplar.h"
#include "../transfer_params.h"
#include "core/error.h"
#include "core/face_plane.h"
#include "core/halo.h"
#include "seams_fixture.h"

namespace maquette::synthesis {
namespace {

using namespace seams;

TEST(FacePlaneSeams, LaysTheRowAndThePolarFacesAsTheGridsTableSays) {
  const FacePlane plane(default_grid());
  EXPECT_EQ(plane.ring_faces(), 4);
  const std::array<std::array<int64_t, 2>, 6> expected = {
      {{0, -1}, {0, 0}, {1, 0}, {2, 0}, {3, 0}, {0, 1}}};  // N O P Q R S
  for (int f = 0; f < 6; ++f) EXPECT_EQ(plane.place(f), expected[size_t(f)]) << "face " << f;
  const CellId cell = CellId::FromFaceColRow(kFaceQ, 3, 5, 6);
  EXPECT_EQ(plane.tile_pixel(cell, 16, 2, -3), (std::array<int64_t, 2>{2 * 128 + 82, 93}));
  EXPECT_EQ(plane.wrap_columns(cell, 16), 4 * 128);
}

// Halo pixel (col, row) of `cell`'s tile: where the store reads it (pixel_source, Grid::wrap) and
// where the plane lays the cell's frame there, as plane pixels (columns modulo the row).
std::array<std::array<int64_t, 2>, 2> halo_places(CellId cell, int col, int row) {
  const Grid& grid = default_grid();
  const FacePlane plane(grid);
  const int64_t period = plane.wrap_columns(cell, kSize);
  const FaceCoord src = *pixel_source(grid, cell, kSize, col, row);
  const auto read = plane.tile_pixel(CellId::FromFace(src.face), int(kFace), src.col, src.row);
  const auto laid = plane.tile_pixel(cell, kSize, col, row);
  return {{{(read[0] % period + period) % period, read[1]},
           {(laid[0] % period + period) % period, laid[1]}}};
}

TEST(FacePlaneSeams, TheStoresHaloLaysANeighbourWhereThePlaneDoes) {
  const uint32_t last = (1u << kLevel) - 1;
  struct Case {
    CellId cell;
    int col, row;
  };
  // Beyond O's right (P), P's left (O), R's right and O's left (the antimeridian), O's top (N),
  // O's bottom (S), N's bottom (O), a few pixels beyond each edge.
  for (const Case& c : {Case{CellId::FromFaceColRow(kFaceO, kLevel, last, kRow), kSize + 3, 7},
                        Case{CellId::FromFaceColRow(kFaceP, kLevel, 0, kRow), -5, 200},
                        Case{CellId::FromFaceColRow(kFaceR, kLevel, last, kRow), kSize + 150, 0},
                        Case{CellId::FromFaceColRow(kFaceO, kLevel, 0, kRow), -1, 255},
                        Case{CellId::FromFaceColRow(kFaceO, kLevel, 9, 0), 30, -20},
                        Case{CellId::FromFaceColRow(kFaceO, kLevel, 9, last), 30, kSize + 4},
                        Case{CellId::FromFaceColRow(kFaceN, kLevel, 3, last), 100, kSize + 1}}) {
    const auto [read, laid] = halo_places(c.cell, c.col, c.row);
    EXPECT_EQ(read, laid) << c.cell.ToText() << " " << c.col << ", " << c.row;
  }
  // Beyond P's top the store reads N turned by 90 degrees: elsewhere in the plane (synthesis.h).
  const auto [read, laid] = halo_places(CellId::FromFaceColRow(kFaceP, kLevel, 9, 0), 30, -20);
  EXPECT_NE(read, laid);
}

TEST(FacePlaneSeams, AFacesChartIsTheStoresHaloButBeyondTheCubeCornersTowardTheRow) {
  const Grid& grid = default_grid();
  const FacePlane plane(grid);
  const int level = kPixelLevel;
  const int64_t n = kFace;
  const auto chart = [&](int face, int64_t col, int64_t row) {
    const FaceCoord p = plane.chart_pixel(grid, face, level, col, row).value();
    return std::array<int64_t, 3>{p.face, p.col, p.row};
  };
  const auto wrap = [&](int face, int64_t col, int64_t row) {
    const FaceCoord p = grid.wrap({face, col, row}, level).value();
    return std::array<int64_t, 3>{p.face, p.col, p.row};
  };
  // Within a face and beyond one edge: the face's pixel and the store's halo's.
  EXPECT_EQ(chart(kFaceP, 5, 7), (std::array<int64_t, 3>{kFaceP, 5, 7}));
  EXPECT_EQ(chart(kFaceP, 5, -7), wrap(kFaceP, 5, -7));
  EXPECT_EQ(chart(kFaceN, n + 5, 9), wrap(kFaceN, n + 5, 9));
  // Beyond P's corner with N and O: above O's last column, where the plane lays N unturned (the
  // store's halo folds it elsewhere).
  EXPECT_EQ(chart(kFaceP, -3, -5), (std::array<int64_t, 3>{kFaceN, n - 3, n - 5}));
  EXPECT_NE(chart(kFaceP, -3, -5), wrap(kFaceP, -3, -5));
  // Beyond N's corner with O and P: P's own pixel, where the plane lays P beside O.
  EXPECT_EQ(chart(kFaceN, n + 2, n + 4), (std::array<int64_t, 3>{kFaceP, 2, 4}));
  // Beyond Q's corner with P and S: below P's last column, S as P's halo reads it.
  EXPECT_EQ(chart(kFaceQ, -2, n + 6), wrap(kFaceP, n - 2, n + 6));
  // Beyond N's corner with P and Q, away from the row: the store's halo.
  EXPECT_EQ(chart(kFaceN, n + 2, -3), wrap(kFaceN, n + 2, -3));
  // Across the antimeridian: beyond O's corner with N and R, above R's last column (N as R's
  // halo reads it); beyond S's corner with O and R and N's with O and R, R's own pixels.
  EXPECT_EQ(chart(kFaceO, -3, -5), wrap(kFaceR, n - 3, -5));
  EXPECT_EQ(chart(kFaceS, -2, -4), (std::array<int64_t, 3>{kFaceR, n - 2, n - 4}));
  EXPECT_EQ(chart(kFaceN, -2, n + 4), (std::array<int64_t, 3>{kFaceR, n - 2, 4}));
  // More than a face width beyond: none, as Grid::wrap.
  EXPECT_FALSE(plane.chart_pixel(grid, kFaceO, level, -n - 1, -1));
  EXPECT_FALSE(grid.wrap({kFaceO, -n - 1, -1}, level));
}

TEST_F(Seams, CellsOnBothSidesOfAnEquatorialEdgeEqualOneSynthesisAcrossIt) {
  // A window of 192 x 64 across the edge between O and P, not aligned with the cells.
  const PixelRect window{kFace - 96, int64_t(kRow) * kSize + 40, 192, 64};
  expect_one_synthesis(window, {CellId::FromFaceColRow(kFaceO, kLevel, (1u << kLevel) - 1, kRow),
                                CellId::FromFaceColRow(kFaceP, kLevel, 0, kRow)});
}

TEST_F(Seams, ACellOfAnotherTilingEqualsTheSynthesisAcrossTheEdge) {
  // P's first cell one level coarser, tiles of 512: the same pixels, another tiling.
  const PixelRect window{kFace - 96, int64_t(kRow) * kSize + 40, 192, 64};
  size_t compared = 0;
  EXPECT_EQ(differing(window, whole(window),
                      CellId::FromFaceColRow(kFaceP, kLevel - 1, 0, kRow / 2), compared, 2 * kSize),
            0u);
  EXPECT_EQ(compared, size_t(window.width * window.height / 2));
}

TEST_F(Seams, CellsOnBothSidesOfTheAntimeridianEqualOneSynthesisAcrossIt) {
  // R's last 96 columns, then O's first 96 (plane columns 4 faces on: the same place).
  const PixelRect window{4 * kFace - 96, int64_t(kRow) * kSize + 150, 192, 64};
  expect_one_synthesis(window, {CellId::FromFaceColRow(kFaceR, kLevel, (1u << kLevel) - 1, kRow),
                                CellId::FromFaceColRow(kFaceO, kLevel, 0, kRow)});
}

TEST_F(Seams, CellsOnBothSidesOfNsEdgeWithOEqualOneSynthesisAcrossIt) {
  // N's last 32 rows above O's first 32 (N is laid unturned above O).
  const PixelRect window{int64_t(kRow) * kSize + 70, -32, 96, 64};
  expect_one_synthesis(window, {CellId::FromFaceColRow(kFaceN, kLevel, kRow, (1u << kLevel) - 1),
                                CellId::FromFaceColRow(kFaceO, kLevel, kRow, 0)});
}

TEST_F(Seams, RefusesAColumnPeriodThatIsNoMultipleOf16) {
  const PixelRect out{0, 0, 16, 16};
  TargetGuides g;
  g.rect = {-200, -200, 416, 416};
  g.labels.assign(size_t(g.rect.width) * size_t(g.rect.height), 0);
  g.col_period = 4 * kFace + 8;  // each level's parity would disagree beyond it
  EXPECT_THROW(synthesize(transfer_exemplar(*params_)->pyramid, g, {}, out), Error);
  g.col_period = 4 * kFace;
  EXPECT_NO_THROW(synthesize(transfer_exemplar(*params_)->pyramid, g, {}, out));
}

}  // namespace
}  // namespace maquette::synthesis
