// `maquette render panorama --antialias` against the analytic outline of a cone (cone_dem.h,
// sampled every 20 m) standing against the sky: the eye 10 km south of its axis, 600 m above its
// foot and 900 m below its apex, looking 4 degrees up, so every ray above the horizontal meets the
// cone or nothing. Above the horizontal the outline is the two tangent generators (cone_view.h),
// straight lines in the picture of the test's own pinhole (test_camera.h): each pixel's share
// inside both (its area sampled 32 x 32) is its analytic coverage. A pixel's colour, in linear
// light (sRGB's transfer function), mixes the sky's colour of its row (a pixel of the row far
// from the cone) and the cone's beside it (two pixels inside along the row): the mix's weight is
// the coverage the picture shows. On the outline's pixels (coverage 0.05 to 0.95, rows from 12
// below the apex to 2 above the horizon) that weight is within a small error of the analytic
// coverage with 4 x 4 samples, and is 0 or 1 (an error of a quarter on average) with one. So is
// the coverage guide (the share of the pixel's samples that see terrain), and it is 0 on the sky
// and 1 on the cone away from the outline. The other guides are the same bytes with and without
// the samples.
#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>
#include <vector>

#include "cone_dem.h"
#include "cone_view.h"
#include "run_cli.h"
#include "test_camera.h"

namespace maquette {
namespace {

constexpr int kWidth = 400, kHeight = 300;

std::vector<uint8_t> read_rgb(const std::string& path) {
  std::unique_ptr<GDALDataset> d(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER));
  std::vector<uint8_t> rgb(size_t(3) * kWidth * kHeight);
  EXPECT_TRUE(d);
  if (d) {
    EXPECT_EQ(d->RasterIO(GF_Read, 0, 0, kWidth, kHeight, rgb.data(), kWidth, kHeight, GDT_Byte, 3,
                          nullptr, 3, 3 * kWidth, 1, nullptr),
              CE_None);
  }
  return rgb;
}

// The guides' band `name` of `path` (a guides GeoTIFF of the picture's size), or empty.
std::vector<double> guide(const std::string& path, const std::string& name) {
  std::unique_ptr<GDALDataset> d(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER));
  EXPECT_TRUE(d) << path;
  for (int b = 1; d && b <= d->GetRasterCount(); ++b) {
    if (d->GetRasterBand(b)->GetDescription() != name) continue;
    std::vector<double> v(size_t(kWidth) * kHeight);
    EXPECT_EQ(d->GetRasterBand(b)->RasterIO(GF_Read, 0, 0, kWidth, kHeight, v.data(), kWidth,
                                            kHeight, GDT_Float64, 0, 0),
              CE_None);
    return v;
  }
  return {};
}

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

double linear(uint8_t byte) {
  const double v = byte / 255.0;
  return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

struct CoverageErrors {
  size_t pixels = 0;
  double mean = 0, p95 = 0;
};

TEST(Antialias, TheConesOutlineAgainstTheSkyCoversEachPixelsShare) {
  const std::string dir = test::temp_dir(), store = dir + "/s.mqt";
  const std::string dem = test::write_utm_dem(dir + "/cone.tif", 600, 20, test::cone_height);
  auto r = test::run_maquette("ingest " + store +
                              " --layer dem --as dem --vertical-datum ellipsoid " + dem);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const double eye_lon = -111, eye_lat = 37.21, eye_height = test::kConeBase + 600;
  const test::TestCamera camera{0, 4, 20, kWidth, kHeight};
  auto render = [&](int samples) {
    const std::string out = dir + "/aa" + std::to_string(samples) + ".png";
    const auto run = test::run_maquette(
        "render panorama " + store + " " + out +
        " --dem dem --camera -111 37.21 1600 --heading 0 --pitch 4 --fov 20 --size 400 300 "
        "--antialias " +
        std::to_string(samples));
    EXPECT_EQ(run.exit_code, 0) << run.err;
    return out;
  };
  const std::string one = render(1), four = render(4);
  for (const char* name : {"altitude", "distance", "lon", "lat", "shading"}) {
    const auto a = guide(dir + "/aa1-guides.tif", name), b = guide(dir + "/aa4-guides.tif", name);
    ASSERT_EQ(a.size(), b.size()) << name;
    EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0) << name;
  }
  EXPECT_TRUE(guide(dir + "/aa1-guides.tif", "coverage").empty());
  const std::vector<double> covered = guide(dir + "/aa4-guides.tif", "coverage");
  ASSERT_EQ(covered.size(), size_t(kWidth) * kHeight);
  EXPECT_EQ(file_bytes(dir + "/aa1-silhouettes.png"), file_bytes(dir + "/aa4-silhouettes.png"));

  // The outline: the two generators, and a point inside both (on the axis, half way up).
  const test::ConeView cone(eye_lon, eye_lat, eye_height);
  const std::vector<double> feet = cone.tangent_azimuths();
  ASSERT_EQ(feet.size(), 2u);
  const auto apex = camera.project(cone.apex());
  std::array<std::array<double, 2>, 2> foot;
  for (int g = 0; g < 2; ++g)
    foot[size_t(g)] = camera.project(cone.at(feet[size_t(g)], test::kConeRadius));
  const auto middle = camera.project(cone.at(0, 0.5 * test::kConeRadius));
  auto side = [&](int g, double x, double y) {
    const auto& b = foot[size_t(g)];
    return (b[0] - apex[0]) * (y - apex[1]) - (b[1] - apex[1]) * (x - apex[0]);
  };
  auto inside = [&](double x, double y) {
    for (int g = 0; g < 2; ++g)
      if ((side(g, x, y) > 0) != (side(g, middle[0], middle[1]) > 0)) return false;
    return true;
  };
  // Pixel (col, row) spans col - 0.5 .. col + 0.5 in the test camera's (OpenCV's) coordinates.
  auto coverage = [&](int col, int row) {
    int in = 0;
    for (int j = 0; j < 32; ++j)
      for (int i = 0; i < 32; ++i)
        in += inside(col - 0.5 + (i + 0.5) / 32, row - 0.5 + (j + 0.5) / 32);
    return in / 1024.0;
  };
  // The horizontal: the row whose ray has no up component at the picture's middle column.
  const double horizon = camera.cy() + camera.focal() * std::tan(4 * M_PI / 180);
  ASSERT_GT(horizon, apex[1] + 40);

  auto errors = [&](const std::vector<uint8_t>& rgb) {
    std::vector<double> e;
    for (int row = int(apex[1]) + 12; row < int(horizon) - 2; ++row) {
      const size_t sky = 3 * (size_t(row) * kWidth + 2);  // the row's far left: sky
      for (int col = 4; col < kWidth - 4; ++col) {
        const double a = coverage(col, row);
        if (a < 0.05 || a > 0.95) continue;
        const int in = col < apex[0] ? col + 2 : col - 2;  // towards the axis: the cone
        if (coverage(in, row) < 1) continue;
        const size_t p = 3 * (size_t(row) * kWidth + size_t(col)),
                     t = 3 * (size_t(row) * kWidth + size_t(in));
        // The band of most contrast between the sky and the cone.
        size_t band = 0;
        for (size_t k = 1; k < 3; ++k)
          if (std::abs(linear(rgb[t + k]) - linear(rgb[sky + k])) >
              std::abs(linear(rgb[t + band]) - linear(rgb[sky + band])))
            band = k;
        const double s = linear(rgb[sky + band]), c = linear(rgb[t + band]);
        const double shown = (linear(rgb[p + band]) - s) / (c - s);
        e.push_back(std::abs(shown - a));
      }
    }
    CoverageErrors out;
    out.pixels = e.size();
    if (e.empty()) return out;
    for (double x : e) out.mean += x / double(e.size());
    std::sort(e.begin(), e.end());
    out.p95 = e[size_t(0.95 * double(e.size() - 1))];
    return out;
  };
  const CoverageErrors aliased = errors(read_rgb(one)), smooth = errors(read_rgb(four));

  // The coverage guide against the analytic coverage on the same outline pixels; 0 where the
  // pixel and its 8 neighbours see the sky at their centres, 1 where they all see terrain (the
  // cone is convex: nothing thinner than a pixel).
  const std::vector<double> distance = guide(dir + "/aa4-guides.tif", "distance");
  size_t sky = 0, ground = 0;
  for (int row = 1; row + 1 < kHeight; ++row)
    for (int col = 1; col + 1 < kWidth; ++col) {
      int terrain = 0;
      for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i)
          terrain += !std::isnan(distance[size_t(row + j) * kWidth + size_t(col + i)]);
      const double c = covered[size_t(row) * kWidth + size_t(col)];
      if (terrain == 0) {
        ++sky;
        EXPECT_EQ(c, 0) << col << ", " << row;
      } else if (terrain == 9) {
        ++ground;
        EXPECT_EQ(c, 1) << col << ", " << row;
      }
    }
  EXPECT_GT(sky, size_t(kWidth) * 50);
  EXPECT_GT(ground, size_t(kWidth) * 50);
  std::vector<double> guide_errors;
  for (int row = int(apex[1]) + 12; row < int(horizon) - 2; ++row)
    for (int col = 4; col < kWidth - 4; ++col) {
      const double a = coverage(col, row);
      if (a < 0.05 || a > 0.95 || coverage(col < apex[0] ? col + 2 : col - 2, row) < 1) continue;
      guide_errors.push_back(std::abs(covered[size_t(row) * kWidth + size_t(col)] - a));
    }
  ASSERT_GT(guide_errors.size(), 100u);
  double guide_mean = 0;
  for (const double x : guide_errors) guide_mean += x / double(guide_errors.size());
  std::sort(guide_errors.begin(), guide_errors.end());
  const double guide_p95 = guide_errors[size_t(0.95 * double(guide_errors.size() - 1))];
  std::cout << "coverage guide error, 4 x 4: mean " << guide_mean << ", p95 " << guide_p95 << "\n";
  EXPECT_LE(guide_mean, 0.05);
  EXPECT_LE(guide_p95, 0.12);
  std::cout << "outline pixels " << smooth.pixels << "; coverage error, 1 sample: mean "
            << aliased.mean << ", p95 " << aliased.p95 << "; 4 x 4: mean " << smooth.mean
            << ", p95 " << smooth.p95 << "\n";
  RecordProperty("mean_error_4x4", std::to_string(smooth.mean));
  EXPECT_GT(smooth.pixels, 100u);
  EXPECT_LE(smooth.mean, 0.05);
  EXPECT_LE(smooth.p95, 0.12);
  EXPECT_GE(aliased.mean, 0.15);  // the measure sees the staircase
}

}  // namespace
}  // namespace maquette
