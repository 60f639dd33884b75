// The projection against PROJ's rhealpix on 100000 random points.
#include <gtest/gtest.h>

#include "proj_rhealpix.h"
#include "rhealpix/rhealpix_grid.h"
#include "test_util.h"

namespace maquette {
namespace {

constexpr double kDeg = M_PI / 180;

// PROJ's forward error: it takes sin beta = q / qp (rounding eps) and sigma =
// sqrt(3 (1 - |sin beta|)), so sigma is off by ~3 eps / (2 sigma), sigma ~ 1.22 cos(lat), which
// is below 1 micrometre only up to ~89.9 degrees; at the pole sin beta = 1 - O(eps) leaves sigma
// ~ sqrt(6 eps). Our own precision there is checked by the round trip and GeographicLib.
double proj_tolerance_m(double lat) {
  constexpr double kEps = 2.2e-16, kRadius = 6371007.180918;
  const double cos_lat = std::cos(lat * kDeg);
  return 1e-6 + kRadius * std::min(4 * kEps / (1.22 * cos_lat), 8 * std::sqrt(kEps));
}

class ProjTest : public ::testing::Test {
 protected:
  PlanePoint proj_forward(LonLat p) const { return proj_.forward(p); }
  LonLat proj_inverse(PlanePoint p) const { return proj_.inverse(p); }

  test::ProjRhealpix proj_;
};

TEST_F(ProjTest, RandomPoints) {
  const Grid& grid = default_grid();
  double max_forward = 0, max_polar = 0, max_inverse = 0, max_round_trip = 0;
  for (const LonLat p : test::random_points(100000)) {
    const PlanePoint ours = grid.forward(p);
    const PlanePoint theirs = proj_forward(p);
    const double d = std::hypot(ours.x - theirs.x, ours.y - theirs.y);
    if (std::abs(p.lat) > 89.9) {
      max_polar = std::max(max_polar, d / proj_tolerance_m(p.lat));
    } else {
      max_forward = std::max(max_forward, d);
    }

    const LonLat back = grid.inverse(ours);
    const LonLat proj_back = proj_inverse(ours);
    const double lon_scale = std::cos(p.lat * kDeg);
    max_inverse = std::max({max_inverse, std::abs(back.lat - proj_back.lat),
                            std::abs(std::remainder(back.lon - proj_back.lon, 360)) * lon_scale});
    max_round_trip = std::max({max_round_trip, std::abs(back.lat - p.lat),
                               std::abs(std::remainder(back.lon - p.lon, 360)) * lon_scale});
  }
  EXPECT_LT(max_forward, 1e-6);
  EXPECT_LT(max_polar, 1);
  // PROJ 9.1's inverse solves the authalic latitude to ~2e-8 degrees only.
  EXPECT_LT(max_inverse, 2e-8);
  EXPECT_LT(max_round_trip, 1e-9);
  RecordProperty("max_forward_m", std::to_string(max_forward));
}

TEST_F(ProjTest, NearPoles) {
  const Grid& grid = default_grid();
  for (const double lat : {89.9, 89.99, 89.999999, 90.0, -89.9, -89.99999, -90.0}) {
    for (double lon = -180; lon < 180; lon += 7.5) {
      const PlanePoint ours = grid.forward({lon, lat});
      const PlanePoint theirs = proj_forward({lon, lat});
      EXPECT_LT(std::hypot(ours.x - theirs.x, ours.y - theirs.y), proj_tolerance_m(lat))
          << lon << " " << lat;
      const LonLat back = grid.inverse(ours);
      EXPECT_NEAR(back.lat, lat, 1e-12) << lon << " " << lat;
      if (std::abs(lat) < 90) {
        EXPECT_NEAR(std::remainder(back.lon - lon, 360), 0, 1e-12 / std::cos(lat * kDeg));
      }
    }
  }
}

// Points on the boundary of every face, computed as meshes and tiles do (left or top edge plus a
// multiple of the pixel size, so the outer edges and corners of the plane come out a few ulps
// either side): all invert, to PROJ's points. A point clearly beyond the plane still throws.
TEST_F(ProjTest, FaceBoundariesInvert) {
  const Grid& grid = default_grid();
  for (int face = 0; face < CellId::kNumFaces; ++face) {
    const PlaneSquare sq = grid.plane_square(CellId::FromFace(face));
    for (const int level : {0, 3, 14}) {
      const int64_t n = int64_t(1) << level;
      const double pixel = sq.side / double(n);
      const int64_t stride = std::max<int64_t>(1, n / 64);
      for (int64_t i = 0; i <= n; i += stride) {
        const double t = double(i) * pixel;
        for (const PlanePoint p : {PlanePoint{sq.x_min + t, sq.y_max},
                                   PlanePoint{sq.x_min + double(n) * pixel, sq.y_max - t},
                                   PlanePoint{sq.x_min + t, sq.y_max - double(n) * pixel},
                                   PlanePoint{sq.x_min, sq.y_max - t}}) {
          LonLat ours;
          ASSERT_NO_THROW(ours = grid.inverse(p)) << face << " " << p.x << " " << p.y;
          EXPECT_LT(test::distance_m(ours, proj_inverse(p)), 5e-3) << p.x << " " << p.y;
        }
      }
    }
  }
  const double r = 6371007.180918;
  EXPECT_THROW(grid.inverse({M_PI * r + 1, 0}), Error);                  // right of R
  EXPECT_THROW(grid.inverse({-M_PI * r - 1, 0}), Error);                 // left of O
  EXPECT_THROW(grid.inverse({0, -M_PI * r / 4 - 1}), Error);             // below Q
  EXPECT_THROW(grid.inverse({-M_PI * r, 3 * M_PI * r / 4 + 1}), Error);  // above N
}

}  // namespace
}  // namespace maquette
