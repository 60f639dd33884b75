// A mosaic's sample <-> lon/lat mapping (core/mosaic_geometry.h) against PROJ's rhealpix: a
// mosaic anchored on face N whose samples run past N's right edge onto P (turned by 90 degrees
// about the corner N, O and P share) and past its bottom edge onto O (unturned). Sample centres
// are PROJ's inverse of the pixel centres' plane points, and PROJ's lon/lat of points between
// centres map back to their fractional sample coordinates; every sample's centre maps back to
// itself for every anchor; gaps and the opposite face have no place.
#include "core/mosaic_geometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "proj_rhealpix.h"
#include "test_util.h"

namespace maquette {
namespace {

constexpr int kLevel = 12;  // pixels of ~2.4 km on the ellipsoid
constexpr int64_t kN = int64_t(1) << kLevel;
constexpr int kSide = 64;  // the mosaic's samples a side
// Sample (0, 0) at anchor-frame (kN - 40, kN - 24): columns 40.. are on P, rows 24.. on O, and
// the quadrant beyond both is the corner gap.
constexpr int64_t kOriginCol = kN - 40, kOriginRow = kN - 24;
constexpr int64_t kPastCol = 40, kPastRow = 24;

class MosaicGeometryTest : public ::testing::Test {
 protected:
  // PROJ's lon/lat of fractional sample (col, row) of the mosaic, outside the corner gap: on N,
  // the plane point of face pixel (origin + col + 0.5, origin + row + 0.5); below N, O's square
  // lies straight under N's; right of N, the offset (dx, dy) from the shared corner is turned
  // clockwise to (dy, -dx), into P's square.
  LonLat proj_lonlat(double col, double row) const {
    const PlaneSquare n = default_grid().plane_square(CellId::FromFace(0));
    const double pixel = n.side / double(kN);
    const double u = (double(kOriginCol) + col + 0.5) * pixel;  // from N's top-left corner
    const double v = (double(kOriginRow) + row + 0.5) * pixel;
    if (u <= n.side) return proj_.inverse({n.x_min + u, n.y_max - v});
    const double dx = u - n.side, dy = n.side - v;
    return proj_.inverse({n.x_min + n.side + dy, n.y_max - n.side - dx});
  }

  test::ProjRhealpix proj_;
};

TEST_F(MosaicGeometryTest, SampleCentresAndFractionsAreWherePROJPutsThem) {
  const Grid& grid = default_grid();
  const MosaicGeometry mosaic(grid, 0, kLevel, kOriginCol, kOriginRow);
  double worst_centre_m = 0, worst_fraction = 0;
  int on_p = 0, on_o = 0;
  for (int row = 0; row < kSide; ++row)
    for (int col = 0; col < kSide; ++col) {
      if (col >= kPastCol && row >= kPastRow) {  // the corner gap
        EXPECT_FALSE(mosaic.sample_lonlat(col, row)) << col << " " << row;
        continue;
      }
      const auto centre = mosaic.sample_lonlat(col, row);
      ASSERT_TRUE(centre) << col << " " << row;
      worst_centre_m = std::max(worst_centre_m, test::distance_m(*centre, proj_lonlat(col, row)));
      const int face = grid.cell_from_point(*centre, 0).face();
      on_p += face == 2, on_o += face == 1;
      // A point between centres, a quarter sample right and 0.3 sample up.
      const double c = col + 0.25, r = row - 0.3;
      const auto at = mosaic.sample(proj_lonlat(c, r));
      ASSERT_TRUE(at) << col << " " << row;
      worst_fraction = std::max({worst_fraction, std::abs((*at)[0] - c), std::abs((*at)[1] - r)});
    }
  EXPECT_EQ(on_p, (kSide - kPastCol) * kPastRow);
  EXPECT_EQ(on_o, kPastCol * (kSide - kPastRow));
  // PROJ's inverse solves the authalic latitude to ~2e-8 degrees (~2 mm), 1e-6 of a sample.
  EXPECT_LT(worst_centre_m, 0.01);
  EXPECT_LT(worst_fraction, 1e-5);
  std::ostringstream measured;
  measured << worst_centre_m << " m, " << worst_fraction << " sample";
  RecordProperty("worst_centre_and_fraction", measured.str());
}

// For every anchor, a mosaic spanning its four neighbours (one face width each side): the centre
// of every 37th sample that has a place maps back to that sample.
TEST(MosaicGeometry, EverySampleCentreMapsBackToItself) {
  const Grid& grid = default_grid();
  constexpr int kCoarse = 6;  // 64 pixels a face side
  constexpr int64_t n = int64_t(1) << kCoarse;
  double worst = 0;
  for (int anchor = 0; anchor < CellId::kNumFaces; ++anchor) {
    const MosaicGeometry mosaic(grid, anchor, kCoarse, -n, -n);  // sample (n, n): anchor (0, 0)
    for (int64_t i = 0; i < 9 * n * n; i += 37) {
      const int64_t col = i % (3 * n), row = i / (3 * n);
      const auto centre = mosaic.sample_lonlat(col, row);
      const bool corner = (col < n || col >= 2 * n) && (row < n || row >= 2 * n);
      ASSERT_EQ(bool(centre), !corner) << anchor << " " << col << " " << row;
      if (!centre) continue;
      const auto back = mosaic.sample(*centre);
      ASSERT_TRUE(back) << anchor << " " << col << " " << row;
      worst =
          std::max({worst, std::abs((*back)[0] - double(col)), std::abs((*back)[1] - double(row))});
    }
  }
  EXPECT_LT(worst, 1e-9);  // the grid's round trip: within 1e-9 degrees; a sample: ~1.4 degrees
}

TEST(MosaicGeometry, TheOppositeFaceHasNoPlace) {
  const Grid& grid = default_grid();
  const MosaicGeometry mosaic(grid, 0, kLevel, 0, 0);  // N
  EXPECT_EQ(grid.cell_from_point({10, -80}, 0).face(), 5);
  EXPECT_FALSE(mosaic.sample({10, -80}));  // on S
  EXPECT_TRUE(mosaic.sample({10, 80}));
}

}  // namespace
}  // namespace maquette
