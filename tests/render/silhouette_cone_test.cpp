// Silhouettes of `maquette render panorama` against the analytic occluding contours of a cone
// (cone_dem.h, sampled every 20 m) on a plain, seen from 10 km south and 5 km above its foot.
// The test's contour: the two generators along which the view rays graze the cone (cone_view.h),
// projected by the test's own pinhole (test_camera.h). The program marks a terrain
// pixel next to one more than 1.05 times farther, so a contour point counts where the plain the
// grazing ray meets behind the cone (its height on a sphere of 6371 km) is that much farther:
// - recall: of the contour's points (every 0.25 px) whose ray meets the plain more than 1.1 times
//   farther, >= 95 % have a silhouette pixel centre within 1 px;
// - precision: of the silhouette pixels nearer than the cone's far side, >= 95 % lie within
//   1 px of a tangent generator (anywhere along it).
// The tolerance: the pixel marked is the near one of the pair across the contour, its centre up
// to 1 px inside it (the mesh's facets depart from the cone by well under 0.1 px here).
#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "cone_dem.h"
#include "cone_view.h"
#include "run_cli.h"
#include "synthetic_raster.h"
#include "test_camera.h"

namespace maquette {
namespace {

using test::dot;
using test::norm;
using test::Vec;

constexpr double kEyeLon = -111, kEyeLat = 37.21, kEyeHeight = 6000;
constexpr double kEarthRadius = 6371000;

// The distance along the ray from the eye through `p` to where it meets the plain (the cone's
// foot height on a sphere), beyond p.
double plain_behind(const Vec& p) {
  const double d = norm(p);
  const Vec u = {p[0] / d, p[1] / d, p[2] / d};
  // height(s) = eye height + s u_up + s^2 (u_e^2 + u_n^2) / 2R
  const double a = (u[0] * u[0] + u[1] * u[1]) / (2 * kEarthRadius), b = u[2],
               c = kEyeHeight - test::kConeBase;
  const double disc = b * b - 4 * a * c;
  return disc < 0 ? INFINITY : (-b - std::sqrt(disc)) / (2 * a);
}

TEST(Silhouettes, ConeContoursWithinOnePixel) {
  const std::string dir = test::temp_dir(), store = dir + "/s.mqt";
  const std::string dem = test::write_utm_dem(dir + "/cone.tif", 600, 20, test::cone_height);
  auto r = test::run_maquette("ingest " + store +
                              " --layer dem --as dem --vertical-datum ellipsoid " + dem);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const test::TestCamera camera{0, -20, 50, 400, 300};
  r = test::run_maquette("render panorama " + store + " " + dir +
                         "/p.png --dem dem --camera -111 37.21 6000 --heading 0 --pitch -20 "
                         "--fov 50 --size 400 300");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  GDALAllRegister();
  std::unique_ptr<GDALDataset> edges(
      GDALDataset::Open((dir + "/p-silhouettes.png").c_str(), GDAL_OF_RASTER));
  std::unique_ptr<GDALDataset> guides(
      GDALDataset::Open((dir + "/p-guides.tif").c_str(), GDAL_OF_RASTER));
  ASSERT_TRUE(edges && guides);
  std::vector<uint8_t> silhouette(400 * 300);
  std::vector<double> distance(400 * 300);
  ASSERT_EQ(edges->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, 400, 300, silhouette.data(), 400, 300,
                                              GDT_Byte, 0, 0),
            CE_None);
  ASSERT_EQ(guides->GetRasterBand(2)->RasterIO(GF_Read, 0, 0, 400, 300, distance.data(), 400, 300,
                                               GDT_Float64, 0, 0),
            CE_None);

  const test::ConeView cone(kEyeLon, kEyeLat, kEyeHeight);
  const std::vector<double> roots = cone.tangent_azimuths();
  ASSERT_EQ(roots.size(), 2u);

  // The contour's points every ~0.25 px, with whether the plain behind is > 1.1 times farther.
  struct ContourPoint {
    double x, y;
    bool jump;
  };
  std::vector<ContourPoint> contour;
  const Vec apex = cone.apex();
  double farthest = 0;  // the cone's far side from the eye
  for (int k = 0; k < 360; ++k)
    farthest = std::max(farthest, norm(cone.at(2 * std::numbers::pi * k / 360, test::kConeRadius)));
  for (const double phi : roots) {
    const Vec foot = cone.at(phi, test::kConeRadius);
    const auto a = camera.project(apex), b = camera.project(foot);
    const int n = int(std::hypot(b[0] - a[0], b[1] - a[1]) * 4) + 1;
    for (int k = 0; k <= n; ++k) {
      const double t = double(k) / n;
      const Vec p = cone.at(phi, t * test::kConeRadius);
      const auto px = camera.project(p);
      contour.push_back({px[0], px[1], plain_behind(p) > 1.1 * norm(p)});
    }
  }
  auto near_contour = [&](double x, double y) {
    for (const ContourPoint& c : contour)
      if (std::hypot(c.x - x, c.y - y) <= 1.0) return true;
    return false;
  };
  size_t wanted = 0, found = 0;
  for (const ContourPoint& c : contour) {
    if (!c.jump) continue;
    ++wanted;
    bool hit = false;
    for (int row = int(c.y) - 2; row <= int(c.y) + 2 && !hit; ++row)
      for (int col = int(c.x) - 2; col <= int(c.x) + 2 && !hit; ++col)
        hit = col >= 0 && row >= 0 && col < 400 && row < 300 &&
              silhouette[size_t(row) * 400 + size_t(col)] &&
              std::hypot(col - c.x, row - c.y) <= 1.0;
    found += hit;
  }
  size_t marked = 0, right = 0;
  for (int row = 0; row < 300; ++row)
    for (int col = 0; col < 400; ++col) {
      const size_t i = size_t(row) * 400 + size_t(col);
      if (!silhouette[i] || !(distance[i] < farthest)) continue;
      ++marked;
      right += near_contour(col, row);
    }
  const double recall = double(found) / double(wanted), precision = double(right) / double(marked);
  std::cout << "cone: " << wanted << " contour points, recall " << recall << "; " << marked
            << " silhouette pixels, precision " << precision << "\n";
  RecordProperty("recall", std::to_string(recall));
  RecordProperty("precision", std::to_string(precision));
  EXPECT_GT(wanted, 300u);
  EXPECT_GE(recall, 0.95);
  EXPECT_GE(precision, 0.95);
}

}  // namespace
}  // namespace maquette
