// Region mosaics across rHEALPix face seams through the runner: a region over faces N and O
// (unturned) and over N and P (P's tiles turned) pasted by the runner for fixture.region_seams,
// which reports each mosaic sample's neighbours; the grid says, by its own wrap, which neighbours
// each pixel has on the ellipsoid. Every stored sample is back at its own pixel (the grid's pixel
// centre), has exactly the neighbours in the mosaic that it has on the ellipsoid among the
// region's cells (seams included), none farther than two pixel sides, the same bits with 1 and 2
// threads; a region around the corner where N, O and P meet is refused, naming a cell of each.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "core/halo.h"
#include "runtime/runner.h"
#include "store/store.h"
#include "test_util.h"

namespace maquette {
namespace {

using nlohmann::json;

constexpr int kLevel = 5, kTile = 16, kPixelLevel = kLevel + 4;  // ~20 km pixels

json seam_pipeline(const std::vector<CellId>& cells) {
  json ids = json::array();
  for (const CellId c : cells) ids.push_back(c.ToText());
  return {{"store", "out.mqt"},
          {"region", {{"cells", ids}}},
          {"level", kLevel},
          {"tile_size", kTile},
          {"steps",
           {{{"op", "fixture.pixel_lonlat"}, {"outputs", {{"lonlat", "ll"}}}},
            {{"op", "fixture.region_seams"},
             {"inputs", {{"src", "ll"}}},
             {"outputs", {{"dst", "seams"}}}}}}};
}

void run_in(const test::TempDir& dir, const json& doc, int threads) {
  RunOptions options;
  options.threads = threads;
  options.quiet = true;
  run_pipeline(test::load_fixture_pipeline(test::write_pipeline(dir, doc)), options);
}

// The cells within 3 degrees of a point on the edge of face N (latitude 41.9).
std::vector<CellId> cells_around(double lon) {
  return default_grid().cover_bbox(lon - 3, 38.9, lon + 3, 44.9, kLevel, Containment::Overlap);
}

void expect_seam_mosaic(double lon, int other_face) {
  const std::vector<CellId> cells = cells_around(lon);
  std::set<int> faces;
  for (const CellId c : cells) faces.insert(c.face());
  ASSERT_EQ(faces, (std::set<int>{0, other_face}));
  test::TempDir one, two;
  run_in(one, seam_pipeline(cells), 1);
  run_in(two, seam_pipeline(cells), 2);
  EXPECT_EQ(test::first_difference(test::snapshot(one.file("out.mqt")),
                                   test::snapshot(two.file("out.mqt"))),
            "");

  const Grid& grid = default_grid();
  const std::set<CellId> region(cells.begin(), cells.end());
  const double pixel_m = std::sqrt(grid.area(kPixelLevel));
  const auto store = Store::open(one.file("out.mqt"), Store::Mode::ReadOnly);
  int misplaced = 0, wrong_neighbours = 0, across_seams = 0;
  double farthest = 0;
  for (const CellId cell : cells) {
    const Tile<float> out = to_tile<float>(*store->get_tile("seams", cell));
    for (int r = 0; r < kTile; ++r)
      for (int c = 0; c < kTile; ++c) {
        const LonLat p = pixel_centre(
            grid, {cell.face(), global_col(cell, kTile, c), global_row(cell, kTile, r)},
            kPixelLevel);
        misplaced += out.at(c, r, 0) != float(p.lon) || out.at(c, r, 1) != float(p.lat);
        int neighbours = 0;
        for (const auto& [dc, dr] : {std::pair{-1, 0}, {1, 0}, {0, -1}, {0, 1}}) {
          const auto q = pixel_source(grid, cell, kTile, c + dc, r + dr);
          const CellId holder = CellId::FromFaceColRow(q->face, kLevel, uint32_t(q->col / kTile),
                                                       uint32_t(q->row / kTile));
          if (!region.count(holder)) continue;
          ++neighbours;
          across_seams += q->face != cell.face();
        }
        wrong_neighbours += out.at(c, r, 2) != float(neighbours);
        farthest = std::max(farthest, double(out.at(c, r, 3)));
      }
  }
  EXPECT_EQ(misplaced, 0);
  EXPECT_EQ(wrong_neighbours, 0);
  EXPECT_GT(across_seams, 2 * kTile);  // the seam runs across at least two cells
  EXPECT_LT(farthest, 2 * pixel_m);
  std::printf(
      "seam N-%c: %zu cells, %d neighbour pairs across the seam, farthest neighbour %.2f "
      "pixel sides\n",
      CellId::kFaceLetters[size_t(other_face)], cells.size(), across_seams, farthest / pixel_m);
}

TEST(RegionSeams, FacesNAndOPasteUnturned) { expect_seam_mosaic(-130, 1); }

TEST(RegionSeams, FacesNAndPPasteTurned) { expect_seam_mosaic(-40, 2); }

TEST(RegionSeams, ThreeFacesAtACornerAreRefused) {
  const std::vector<CellId> cells = cells_around(-90);  // N, O and P meet at lon -90
  std::vector<CellId> first;
  for (const CellId c : cells)
    if (first.empty() || first.back().face() != c.face()) first.push_back(c);
  ASSERT_EQ(first.size(), 3u);
  test::TempDir dir;
  EXPECT_EQ(test::error_of([&] { run_in(dir, seam_pipeline(cells), 2); }),
            dir.file("pipeline.json") + ": step 2 (fixture.region_seams): the region's cells " +
                first[0].ToText() + " (face N), " + first[1].ToText() + " (face O) and " +
                first[2].ToText() +
                " (face P) lie on three faces meeting at a corner, which leave a gap when "
                "unfolded into one plane: split the region there");
}

}  // namespace
}  // namespace maquette
