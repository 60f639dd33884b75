// The colour ramps of `export png` for quantities other than heights, through the program:
// viridis by default (checked against GRASS's viridis table, matplotlib's, read as an independent
// oracle), a diverging ramp centred on 0 for values of both signs, grey on request, and a legend
// drawn in the same ramp. The layers are linear in longitude, so each pixel's value is known from
// the PNG's georeferencing.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "run_cli.h"
#include "synthetic_raster.h"

namespace maquette::test {
namespace {

namespace fs = std::filesystem;
using Rgb = std::array<double, 3>;

// GRASS's viridis colour rules ("P% R:G:B" lines), as stops; empty when GRASS is not installed.
std::vector<std::pair<double, Rgb>> grass_viridis() {
  std::vector<std::pair<double, Rgb>> stops;
  for (const std::string dir : {"/usr/lib/grass82", "/usr/lib/grass83", "/usr/lib/grass84"}) {
    std::ifstream in(dir + "/etc/colors/viridis");
    for (std::string line; std::getline(in, line);) {
      double p = 0;
      Rgb c{};
      if (std::sscanf(line.c_str(), "%lf%% %lf:%lf:%lf", &p, &c[0], &c[1], &c[2]) == 4)
        stops.push_back({p / 100, c});
    }
    if (!stops.empty()) break;
  }
  return stops;
}

Rgb interpolate(const std::vector<std::pair<double, Rgb>>& stops, double t) {
  size_t i = 1;
  while (i + 1 < stops.size() && t > stops[i].first) ++i;
  const auto& [t0, a] = stops[i - 1];
  const auto& [t1, b] = stops[i];
  const double w = std::clamp((t - t0) / (t1 - t0), 0.0, 1.0);
  return {a[0] + w * (b[0] - a[0]), a[1] + w * (b[1] - a[1]), a[2] + w * (b[2] - a[2])};
}

// A store holding layer "q" (`--as climate`, no units): value(lon) on 7..8 E, 45..46 N.
std::string store_of(const std::string& dir, double (*value)(double lon)) {
  const std::string tif = dir + "/q.tif", store = dir + "/s.mqt";
  write_raster(tif, lonlat_raster(7, 46, 200, 0.005, "Float32"),
               [value](int, double lon, double) { return value(lon); });
  const CliResult r = run_maquette("-q ingest " + store + " --layer q --as climate " + tif);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return store;
}

struct Picture {
  cv::Mat png;
  double x0 = 0, dx = 0;  // the world file's first pixel centre and pixel size, in longitude
};

Picture export_png(const std::string& store, const std::string& extra) {
  const std::string out = fs::path(store).parent_path() / "q.png";
  const CliResult r = run_maquette("-q export png " + store + " --layer q " + out + " " + extra);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  Picture p{cv::imread(out, cv::IMREAD_UNCHANGED)};
  std::ifstream world(fs::path(out).replace_extension("pgw"));
  double rot1 = 0, rot2 = 0, dy = 0, y0 = 0;
  world >> p.dx >> rot1 >> rot2 >> dy >> p.x0 >> y0;
  return p;
}

// Calls check(value's longitude, RGB) on every opaque map pixel of every 7th row and column.
template <class Check>
void each_pixel(const Picture& p, Check&& check) {
  for (int r = 0; r < p.png.rows; r += 7)
    for (int c = 0; c < p.png.cols; c += 7)
      if (const auto& q = p.png.at<cv::Vec4b>(r, c); q[3] == 255)
        check(p.x0 + c * p.dx, Rgb{double(q[2]), double(q[1]), double(q[0])});
}

// The longest run of coloured (not white, not transparent) pixels in the legend's rows (those
// starting with white paper, below the map): the colour bar.
std::vector<Rgb> legend_bar(const cv::Mat& png) {
  const auto paper = [](const cv::Vec4b& q) {
    return q[0] == 255 && q[1] == 255 && q[2] == 255 && q[3] == 255;
  };
  std::vector<Rgb> best;
  for (int r = 0; r < png.rows; ++r) {
    if (!paper(png.at<cv::Vec4b>(r, 0))) continue;
    std::vector<Rgb> run;
    for (int c = 0; c <= png.cols; ++c) {
      const cv::Vec4b q = c < png.cols ? png.at<cv::Vec4b>(r, c) : cv::Vec4b(255, 255, 255, 255);
      if (!paper(q) && q[3] == 255) {
        run.push_back({double(q[2]), double(q[1]), double(q[0])});
      } else {
        if (run.size() > best.size()) best = run;
        run.clear();
      }
    }
  }
  return best;
}

double distance(const Rgb& a, const Rgb& b) {
  return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

TEST(PngRamps, QuantitiesAreDrawnInViridisAsGrassHasIt) {
  const auto viridis = grass_viridis();
  if (viridis.size() < 100) GTEST_SKIP() << "GRASS's viridis table is not installed";
  const std::string store = store_of(temp_dir(), [](double lon) { return 100 * (lon - 7); });
  const Picture p = export_png(store, "--range 0 100 --no-legend");
  ASSERT_FALSE(p.png.empty());
  int n = 0;
  double worst = 0;
  each_pixel(p, [&](double lon, const Rgb& rgb) {
    worst = std::max(worst, distance(rgb, interpolate(viridis, lon - 7)));
    ++n;
  });
  EXPECT_GT(n, 500);
  EXPECT_LE(worst, 6) << "the largest channel difference from GRASS's viridis";
  // The legend's bar runs from viridis(0) to viridis(1).
  const std::vector<Rgb> bar = legend_bar(export_png(store, "--range 0 100").png);
  ASSERT_GT(bar.size(), 100U);
  EXPECT_LE(distance(bar.front(), interpolate(viridis, 0)), 8);
  EXPECT_LE(distance(bar.back(), interpolate(viridis, 1)), 8);
}

TEST(PngRamps, SignedQuantitiesGetADivergingRampCentredOnZero) {
  // -10 .. 30: zero at 7.25 E.
  const std::string store = store_of(temp_dir(), [](double lon) { return 40 * (lon - 7) - 10; });
  const Picture p = export_png(store, "--no-legend");
  ASSERT_FALSE(p.png.empty());
  int near_zero = 0, negative = 0, positive = 0;
  each_pixel(p, [&](double lon, const Rgb& rgb) {
    const double v = 40 * (lon - 7) - 10;
    if (std::abs(v) < 0.3) {
      ++near_zero;
      EXPECT_GE(std::min({rgb[0], rgb[1], rgb[2]}), 235) << "v " << v;
    } else if (v < -6) {
      ++negative;
      EXPECT_GT(rgb[2] - rgb[0], 20) << "v " << v << ": blue";
    } else if (v > 6) {
      ++positive;
      EXPECT_GT(rgb[0] - rgb[2], 20) << "v " << v << ": red";
    }
  });
  EXPECT_GT(near_zero, 5);
  EXPECT_GT(negative, 100);
  EXPECT_GT(positive, 100);
  // The bar is symmetric around 0: near-white in its middle, blue and red at its ends.
  const std::vector<Rgb> bar = legend_bar(export_png(store, "").png);
  ASSERT_GT(bar.size(), 100U);
  EXPECT_GE(bar[bar.size() / 2][1], 235);
  EXPECT_GT(bar.front()[2] - bar.front()[0], 50);
  EXPECT_GT(bar.back()[0] - bar.back()[2], 50);
}

TEST(PngRamps, AnAskedRangeIsTheDivergingRampsEnds) {
  // -10 .. 30 drawn with --range -30 70: 20 gets the middle colour, not 0 (the ramp is not widened
  // to +-70 around 0).
  const std::string store = store_of(temp_dir(), [](double lon) { return 40 * (lon - 7) - 10; });
  const Picture p = export_png(store, "--ramp diverging --range -30 70 --no-legend");
  ASSERT_FALSE(p.png.empty());
  int middle = 0, low = 0;
  each_pixel(p, [&](double lon, const Rgb& rgb) {
    const double v = 40 * (lon - 7) - 10;
    if (std::abs(v - 20) < 1) {
      ++middle;
      EXPECT_GE(std::min({rgb[0], rgb[1], rgb[2]}), 235) << "v " << v;
    } else if (v < 0) {
      ++low;
      EXPECT_GT(rgb[2] - rgb[0], 20) << "v " << v << ": blue";
    }
  });
  EXPECT_GT(middle, 5);
  EXPECT_GT(low, 50);
}

TEST(PngRamps, GreyOnRequest) {
  const std::string store = store_of(temp_dir(), [](double lon) { return 100 * (lon - 7); });
  const Picture p = export_png(store, "--ramp grey --range 0 100 --no-legend");
  ASSERT_FALSE(p.png.empty());
  int n = 0;
  each_pixel(p, [&](double lon, const Rgb& rgb) {
    ++n;
    EXPECT_TRUE(rgb[0] == rgb[1] && rgb[1] == rgb[2]);
    EXPECT_NEAR(rgb[0], 255 * (lon - 7), 2);
  });
  EXPECT_GT(n, 500);
}

}  // namespace
}  // namespace maquette::test
