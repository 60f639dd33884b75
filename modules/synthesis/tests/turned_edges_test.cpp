// synthesis.transfer across the polar faces' turned edges (issue 18, turned_edges.h). N's right
// edge meets P's top turned by 90 degrees: N's pixel (X, Y) is P's (kFace - 1 - Y, X - kFace) in
// P's frame continued above it, laid here by hand (and checked against the store's halo). Then:
// the band of an N cell along that edge takes, between the edge and a cut, one synthesis of a
// window across the edge in P's chart computed here (and P's cell that same synthesis on its
// side), and beyond the cut the plane's synthesis of N (N's chart, P turned beside it). The cut
// is the minimum-error one of those two syntheses, computed here. At an output finer than the
// land cover (refine 1) too, P's chart continues into N's band. A cell of another tiling gives
// the same bits. Across each of the six turned edges (N and S with P, Q, R) the sources continue
// as coherently as within a face. Up to the cube corners, two equatorial cells meet as one
// synthesis and the bands continue the equatorial face's chart: the plane continued (the ring's
// face at each column, then across its edge beyond the row, laid here with Grid::wrap), where the
// store's halo folds.
#include "../turned_edges.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdlib>
#include <string>
#include <tuple>
#include <vector>

#include "../seam_cut.h"
#include "core/error.h"
#include "core/halo.h"
#include "seams_fixture.h"

namespace maquette::synthesis {
namespace {

using namespace seams;

class TurnedEdges : public Seams {
 public:
  using Seams::Lay;
  using Seams::plane_pixel;
  using Seams::transfer;
  using Seams::whole;
  static std::shared_ptr<const TransferExemplar> exemplar() { return transfer_exemplar(*params_); }
  static SynthesisParams sp() { return synthesis_params(*params_); }
};

constexpr int kBand = 32;                                 // turned_edges.h's kTurnedEdgeBand
constexpr int kPin = 64;                                  // and kTurnedEdgePin
constexpr uint32_t kLast = (1u << kLevel) - 1;            // N's right column of cells
constexpr int64_t kEdgeCol = kFace - (kRow + 1) * kSize;  // P's first column beside that cell

// P's chart at kPixelLevel (plane pixels): N laid turned above P, as P's cells see it.
FaceCoord p_chart(int64_t x, int64_t r) {
  if (r < 0 && x >= kFace && x < 2 * kFace) return {kFaceN, kFace + r, kFace - 1 - (x - kFace)};
  return TurnedEdges::plane_pixel(x, r);
}
// N's chart: the plane, with P laid turned to the right of N, as N's cells see it.
FaceCoord n_chart(int64_t x, int64_t r) {
  if (r < 0 && x >= kFace && x < 2 * kFace) return {kFaceP, -1 - r, x - kFace};
  return TurnedEdges::plane_pixel(x, r);
}

// The equatorial faces' chart: the plane's row, and beyond it the ring's face at that column
// continued across its top or bottom edge as the grid's adjacency lays it (where the store's halo
// folds the quadrant diagonally beyond a cube corner).
FaceCoord ring_chart(int64_t x, int64_t r) {
  if (r >= 0 && r < kFace) return TurnedEdges::plane_pixel(x, r);
  return *default_grid().wrap({kFaceO + int(x / kFace), x % kFace, r}, kPixelLevel);
}

TEST(TurnedEdgeCharts, TheChartsLaidByHandAreTheStoresHalo) {
  const Grid& grid = default_grid();
  const CellId n = CellId::FromFaceColRow(kFaceN, kLevel, kLast, kRow);
  const CellId p = CellId::FromFaceColRow(kFaceP, kLevel, uint32_t(kEdgeCol / kSize), 0);
  for (const auto& [col, row] : {std::array{kSize + 5, 100}, std::array{kSize + 150, 3}}) {
    const auto src = *pixel_source(grid, n, kSize, col, row);
    const auto laid = n_chart(kFace + col - kSize, -kFace + int64_t(kRow) * kSize + row);
    EXPECT_EQ((std::array<int64_t, 3>{src.face, src.col, src.row}),
              (std::array<int64_t, 3>{laid.face, laid.col, laid.row}));
  }
  for (const auto& [col, row] : {std::array{30, -20}, std::array{255, -1}}) {
    const auto src = *pixel_source(grid, p, kSize, col, row);
    const auto laid = p_chart(kFace + kEdgeCol + col, row);
    EXPECT_EQ((std::array<int64_t, 3>{src.face, src.col, src.row}),
              (std::array<int64_t, 3>{laid.face, laid.col, laid.row}));
  }
}

TEST_F(TurnedEdges, NsBandIsPsChartToTheMinimumErrorCutThenItsOwn) {
  // B: P's chart over the 32 rows above P (N's band) and P's first 32; A: the plane's N.
  const PixelRect across{kFace + kEdgeCol, -kBand, kSize, 2 * kBand};
  const auto b = whole(across, p_chart);
  const PixelRect own{kFace - 48, -kFace + int64_t(kRow) * kSize, 48, kSize};
  const auto a = whole(own, n_chart);
  size_t compared = 0;
  EXPECT_EQ(
      differing(across, b, CellId::FromFaceColRow(kFaceP, kLevel, kEdgeCol / kSize, 0), compared),
      0u);
  EXPECT_EQ(compared, size_t(kSize * kBand));

  // The cut the band must take: the minimum-error cut (seam_cut.h, itself checked against the
  // exhaustive search in seam_cut_test.cpp) of the squared RGB error between a and b. N's row r
  // lies along P's column kEdgeCol + kSize - 1 - r, the band's position i = kSize - 1 - r.
  const auto b_at = [&](int r, int t) {
    return b[size_t((kBand - 1 - t) * kSize + (kSize - 1 - r))];
  };
  const auto a_at = [&](int r, int t) { return a[size_t(r * 48 + 47 - t)]; };
  const ExemplarLevel& colours = transfer_exemplar(*params_)->pyramid.levels[0];
  const auto colour = [&](const std::array<int, 2>& s, int k) {
    return colours.rgb[3 * (size_t(s[1]) * size_t(colours.width) + size_t(s[0])) + size_t(k)];
  };
  std::vector<float> error(size_t(kSize) * kBand);
  for (int r = 0; r < kSize; ++r)
    for (int t = 0; t < kBand; ++t) {
      float d = 0;
      for (int k = 0; k < 3; ++k) {
        const float v = colour(b_at(r, t), k) - colour(a_at(r, t), k);
        d += v * v;
      }
      error[size_t(t * kSize + kSize - 1 - r)] = d;
    }
  const std::vector<int> cut = seam_cut(error, kEdgeCol, kSize, kBand, kPin);
  static_assert(kEdgeCol % kPin == 0);  // the pins: every kPin-th position from the first
  for (int i = 0; i < kSize; i += kPin) EXPECT_EQ(cut[size_t(i)], kBand / 2) << i;

  // Every pixel of N's 48 columns beside the edge: B before the cut, A beyond it.
  const Tile<float> out = transfer(CellId::FromFaceColRow(kFaceN, kLevel, kLast, kRow), kSize);
  size_t wrong = 0, took_b = 0, took_a = 0;
  for (int r = 0; r < kSize; ++r)
    for (int t = 0; t < 48; ++t) {
      const bool takes_b = t < cut[size_t(kSize - 1 - r)];
      const auto& e = takes_b ? b_at(r, t) : a_at(r, t);
      wrong +=
          out.at(kSize - 1 - t, r, 0) != float(e[0]) || out.at(kSize - 1 - t, r, 1) != float(e[1]);
      const bool differ = t < kBand && b_at(r, t) != a_at(r, t);
      took_b += differ && takes_b;
      took_a += differ && !takes_b;
    }
  EXPECT_EQ(wrong, 0u);
  // Both sides of the cut hold a good share of the band.
  EXPECT_GT(took_b, size_t(kSize * kBand / 5));
  EXPECT_GT(took_a, size_t(kSize * kBand / 5));
}

// Pixels of N's cell (kLast, row) at kLevel (tiles of kSize, output `refine` levels finer) whose
// source differs from that of the same pixel in N's cell one level coarser (tiles of 2 * kSize).
size_t differs_from_the_coarser_tiling(uint32_t row, int refine) {
  const Tile<float> fine =
      TurnedEdges::transfer(CellId::FromFaceColRow(kFaceN, kLevel, kLast, row), kSize, refine);
  const Tile<float> coarse = TurnedEdges::transfer(
      CellId::FromFaceColRow(kFaceN, kLevel - 1, kLast / 2, row / 2), 2 * kSize, refine);
  const int n = kSize << refine, dr = int(row % 2) * n;
  size_t differ = 0;
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c)
      for (int k = 0; k < 2; ++k) differ += fine.at(c, r, k) != coarse.at(c + n, r + dr, k);
  return differ;
}

TEST_F(TurnedEdges, ACellOfAnotherTilingGivesTheSameBits) {
  // N's cell one level coarser (tiles of 512) holds the level-5 cell as a quarter: beside P's
  // edge, at the corner where N meets P and Q (two bands, a folded halo quadrant), and at the
  // corner where N meets O and P (P's band meets A along the diagonal, the quadrant laid in N's
  // chart).
  for (const uint32_t row : {kRow, 0u, kLast})
    EXPECT_EQ(differs_from_the_coarser_tiling(row, 0), 0u) << "row " << row;
}

TEST_F(TurnedEdges, AtRefine1ACellOfAnotherTilingGivesTheSameBits) {
  // The pins along the edge come from the output's pixels (tiles of 512 and 1024 here).
  EXPECT_EQ(differs_from_the_coarser_tiling(kRow, 1), 0u);
}

// Of the pixels of the equatorial cell `cell`'s edge row (row 0 for N above it, the last for S
// below), the fraction whose neighbour across the edge (read where the store's halo reads it) has
// the coherent source (its own shifted by the step across), and the same fraction one row inside.
std::array<double, 2> coherence(CellId cell, bool top) {
  const Grid& grid = default_grid();
  const int n = kSize, edge = top ? 0 : n - 1, step = top ? -1 : 1;
  const auto across_edge = [&](int c) { return *pixel_source(grid, cell, n, c, edge + step); };
  const FaceCoord first = across_edge(0);
  const CellId polar = CellId::FromFaceColRow(first.face, cell.level(), uint32_t(first.col / n),
                                              uint32_t(first.row / n));
  const Tile<float> here = TurnedEdges::transfer(cell, kSize);
  const Tile<float> there = TurnedEdges::transfer(polar, kSize);
  size_t across = 0, inside = 0;
  for (int c = 0; c < n; ++c) {
    const FaceCoord q = across_edge(c);
    EXPECT_EQ(
        CellId::FromFaceColRow(q.face, cell.level(), uint32_t(q.col / n), uint32_t(q.row / n)),
        polar);
    const int qc = int(q.col % n), qr = int(q.row % n);
    across += there.at(qc, qr, 0) == here.at(c, edge, 0) &&
              there.at(qc, qr, 1) == here.at(c, edge, 1) + float(step);
    inside += here.at(c, edge - step, 0) == here.at(c, edge, 0) &&
              here.at(c, edge - step, 1) == here.at(c, edge, 1) - float(step);
  }
  return {double(across) / n, double(inside) / n};
}

TEST_F(TurnedEdges, TheSourcesContinueAcrossEachTurnedEdgeAsWithinAFace) {
  for (const int face : {kFaceP, kFaceQ, kFaceR})
    for (const bool top : {true, false}) {
      const CellId cell = CellId::FromFaceColRow(face, kLevel, kRow, top ? 0 : kLast);
      const auto [across, inside] = coherence(cell, top);
      EXPECT_GT(inside, 0.2) << cell.ToText();
      EXPECT_GT(across, 0.7 * inside) << cell.ToText() << (top ? " N" : " S");
    }
}

// The band of the polar cell across the edge row of the equatorial cell `cell` (row 0 for N above
// it, the last for S below) against one synthesis of the 256 x 64 window across that edge in
// `cell`'s chart, laid by `chart` (by default from the store's halo of `cell`, pixel_source: not
// UnfoldedFaces nor turned_edges.h). The band is that synthesis beside the edge, and to a depth
// of at least kBand / 2 at each pin (where the cut lies at kBand / 2), whatever the side and the
// turn; but at column `corner` (the cube corner where the polar face meets the face it is laid
// against), whose pixels are nearer that edge, and at the pins within kBand of it.
void expect_band_continues_the_chart(CellId cell, bool top, const TurnedEdges::Lay& chart = {},
                                     int corner = -1) {
  const Grid& grid = default_grid();
  const int edge = top ? 0 : kSize - 1, step = top ? -1 : 1;
  const auto first = FacePlane(grid).tile_pixel(cell, kSize, 0, 0);
  const PixelRect across{first[0], first[1] + (top ? -kBand : kSize - kBand), kSize, 2 * kBand};
  const auto b = TurnedEdges::whole(
      across, chart ? chart : [&](int64_t x, int64_t r) {
        return *pixel_source(grid, cell, kSize, int(x - first[0]), int(r - first[1]));
      });
  const FaceCoord polar_pixel = *pixel_source(grid, cell, kSize, 0, edge + step);
  const Tile<float> polar = TurnedEdges::transfer(
      CellId::FromFaceColRow(polar_pixel.face, kLevel, uint32_t(polar_pixel.col / kSize),
                             uint32_t(polar_pixel.row / kSize)),
      kSize);
  size_t beside = 0, short_pins = 0;
  for (int c = 0; c < kSize; ++c) {
    int matching = 0;  // depths 0 .. matching - 1 are the chart's
    for (int t = 0; t < kBand && matching == t; ++t) {
      const FaceCoord q = *pixel_source(grid, cell, kSize, c, edge + step * (1 + t));
      const auto& e = b[size_t((top ? kBand - 1 - t : kBand + t) * kSize + c)];
      const int qc = int(q.col % kSize), qr = int(q.row % kSize);
      matching += polar.at(qc, qr, 0) == float(e[0]) && polar.at(qc, qr, 1) == float(e[1]);
    }
    beside += c != corner && matching == 0;
    short_pins +=
        c % kPin == 0 && (corner < 0 || std::abs(c - corner) >= kBand) && matching < kBand / 2;
  }
  EXPECT_EQ(beside, 0u) << cell.ToText();
  EXPECT_EQ(short_pins, 0u) << cell.ToText();
}

TEST_F(TurnedEdges, SsBandsContinueTheChartsOfPQAndRFromTheStoresHalo) {
  for (const int face : {kFaceP, kFaceQ, kFaceR})
    expect_band_continues_the_chart(CellId::FromFaceColRow(face, kLevel, kRow, kLast), false);
}

TEST_F(TurnedEdges, AcrossTheHalfTurnNsBandContinuesQsChartFromTheStoresHalo) {
  expect_band_continues_the_chart(CellId::FromFaceColRow(kFaceQ, kLevel, kRow, 0), true);
}

TEST_F(TurnedEdges, UpToTheCubeCornersTheBandsContinueTheEquatorialFacesChart) {
  // P's first cell under N (the corner N, O, P: N's edge with O laid unturned), its last (N, P,
  // Q: two turned edges) and R's last cell over S (S, R, O). The store's halo folds the quadrant
  // beyond each corner; the band lays the plane continued there, as the equatorial cells do.
  expect_band_continues_the_chart(CellId::FromFaceColRow(kFaceP, kLevel, 0, 0), true, ring_chart,
                                  0);
  expect_band_continues_the_chart(CellId::FromFaceColRow(kFaceP, kLevel, kLast, 0), true,
                                  ring_chart);
  expect_band_continues_the_chart(CellId::FromFaceColRow(kFaceR, kLevel, kLast, kLast), false,
                                  ring_chart, kSize - 1);
}

TEST_F(TurnedEdges, AtTheCornerWithTheUnturnedEdgeThePixelsNearerItKeepNsOwnSynthesis) {
  // N's cell at its corner with O and P: N's pixel (X, Y) is plane (X, Y - F) and P's chart
  // (F - 1 - Y, X - F). A: the plane's N (N's chart, laid by hand: P turned beside it, P's own
  // pixels beyond the corner); B: P's chart over its first cell's band.
  const PixelRect own{kFace - 64, -64, 64, 64};
  const auto a = whole(own, n_chart);
  const PixelRect across{kFace, -kBand, kSize, 2 * kBand};
  const auto b = whole(across, p_chart);
  const Tile<float> out = transfer(CellId::FromFaceColRow(kFaceN, kLevel, kLast, kLast), kSize);
  size_t kept = 0, wrong = 0, differ = 0;
  for (int r = kSize - 64; r < kSize; ++r)
    for (int c = kSize - kBand; c < kSize; ++c) {
      const int depth = kSize - 1 - c, unturned = kSize - 1 - r;  // from P's edge, from O's
      if (unturned > depth) continue;                             // nearer P's edge: the band's
      const auto& e = a[size_t((r - (kSize - 64)) * 64 + c - (kSize - 64))];
      const auto& other = b[size_t((kBand - 1 - depth) * kSize + unturned)];
      ++kept;
      wrong += out.at(c, r, 0) != float(e[0]) || out.at(c, r, 1) != float(e[1]);
      differ += e != other;
    }
  EXPECT_EQ(kept, size_t(kBand * (kBand + 1) / 2));
  EXPECT_EQ(wrong, 0u);
  EXPECT_GT(differ, kept / 2);  // there A and B differ: the rule decides
}

TEST_F(TurnedEdges, UpToTheCubeCornersTwoEquatorialCellsMeetAsOneSynthesis) {
  // O's last cell and P's first under N (the corner N, O, P), P's last and Q's first under N
  // (N, P, Q), Q's last and R's first over S (S, Q, R), R's last and O's first under N across the
  // antimeridian (N, R, O): the quadrant beyond each corner in each cell's halo is the plane
  // continued, so both read the same guides there.
  for (const auto& [left, right, row] :
       {std::tuple{kFaceO, kFaceP, 0u}, std::tuple{kFaceP, kFaceQ, 0u},
        std::tuple{kFaceQ, kFaceR, kLast}, std::tuple{kFaceR, kFaceO, 0u}}) {
    const int64_t edge = int64_t(right - kFaceO) * kFace;
    const PixelRect window{edge - 64, int64_t(row) * kSize, 128, kSize};
    const auto expected = whole(window, ring_chart);
    size_t compared = 0;
    for (const CellId cell : {CellId::FromFaceColRow(left, kLevel, kLast, row),
                              CellId::FromFaceColRow(right, kLevel, 0, row)})
      EXPECT_EQ(differing(window, expected, cell, compared), 0u) << cell.ToText();
    EXPECT_EQ(compared, size_t(window.width * window.height));
  }
}

TEST_F(TurnedEdges, AtAFinerOutputThanTheLandCoverTooPsChartContinuesIntoNsBand) {
  // Output one level finer than the guides (refine 1, tiles of 512 from 256): P's chart over
  // N's 64 rows above P and P's first 64, at level 14, its guides laid by hand at level 13.
  const int n = 2 * kSize;
  const PixelRect across{2 * (kFace + kEdgeCol), -64, n, 128};
  const auto b = whole(across, p_chart, 1);
  const auto differs = [&](const Tile<float>& out, int c, int r, int bc, int br) {
    const auto& e = b[size_t(br * n + bc)];
    return out.at(c, r, 0) != float(e[0]) || out.at(c, r, 1) != float(e[1]);
  };
  const Tile<float> p =
      transfer(CellId::FromFaceColRow(kFaceP, kLevel, kEdgeCol / kSize, 0), kSize, 1);
  size_t in_p = 0;
  for (int r = 0; r < 64; ++r)
    for (int c = 0; c < n; ++c) in_p += differs(p, c, r, c, r + 64);
  EXPECT_EQ(in_p, 0u);
  // N's pixel at depth t from the edge, row r of its cell: P's chart row -1 - t, column n - 1 - r.
  const Tile<float> north = transfer(CellId::FromFaceColRow(kFaceN, kLevel, kLast, kRow), kSize, 1);
  size_t beside = 0, in_band = 0;
  for (int t = 0; t < 2 * kBand; ++t)
    for (int r = 0; r < n; ++r) {
      const bool d = differs(north, n - 1 - t, r, n - 1 - r, 63 - t);
      beside += t == 0 && d;
      in_band += t < kBand && !d;
    }
  EXPECT_EQ(beside, 0u);
  EXPECT_GT(in_band, size_t(n * kBand / 5));
}

// join_turned_edges on N's cell beside P with guides of `halo` pixels a side (all class 0):
// the message of the maquette::Error it throws, or "" if none.
std::string join_error(int halo, bool distance) {
  const Grid& grid = default_grid();
  const CellId cell = CellId::FromFaceColRow(kFaceN, kLevel, kLast, kRow);
  const auto edges = turned_edges(grid, FacePlane(grid), cell, kSize, 0);
  EXPECT_EQ(edges.size(), 1u);
  TargetGuides guides;
  const int side = kSize + 2 * halo;
  guides.rect = {0, 0, side, side};
  guides.labels.assign(size_t(side) * size_t(side), 0);
  if (distance) guides.distance.assign(guides.labels.size(), 1.0f);
  try {
    join_turned_edges(grid, FacePlane(grid), TurnedEdges::exemplar()->pyramid, TurnedEdges::sp(),
                      guides, halo, edges, std::vector<int32_t>(size_t(kSize) * kSize));
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST_F(TurnedEdges, ABandBeyondTheGuidesHaloOrWithGuidesItDoesNotLayIsAnErrorNamingTheCell) {
  const std::string cell = CellId::FromFaceColRow(kFaceN, kLevel, kLast, kRow).ToText();
  const std::string small = join_error(100, false);
  EXPECT_NE(small.find(cell + "'s band along face 2 needs guides beyond its halo of 100"),
            std::string::npos)
      << small;
  const int halo = operator_->spec().halo;
  EXPECT_EQ(join_error(halo, false), "");
  const std::string distance = join_error(halo, true);
  EXPECT_NE(
      distance.find(cell + "'s band along a turned edge lays no distance, depth or light guides"),
      std::string::npos)
      << distance;
}

TEST(TurnedEdgeTiles, OnAPolarFaceTilesNotAPowerOfTwoOrFinerThanThePinsAreAnError) {
  const Grid& grid = default_grid();
  const FacePlane plane(grid);
  const CellId polar = CellId::FromFaceColRow(kFaceN, kLevel, kLast, kRow);
  EXPECT_THROW(turned_edges(grid, plane, polar, 384, 0), Error);
  EXPECT_THROW(turned_edges(grid, plane, polar, 32, 0), Error);
  EXPECT_EQ(turned_edges(grid, plane, polar, 32, 1).size(), 1u);
  EXPECT_TRUE(
      turned_edges(grid, plane, CellId::FromFaceColRow(kFaceP, kLevel, 0, 0), 384, 0).empty());
}

}  // namespace
}  // namespace maquette::synthesis
