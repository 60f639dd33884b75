// LayerSampler::Read::kSmoothLabels (image/layer_sampler.h) on categorical layers written here,
// each a shape quantized to its cells as a land-cover raster quantizes a boundary: a straight
// boundary at eight angles and a disc. The boundary each read draws is found along rays across
// it (bisection to a thousandth of a cell) and compared with the shape: the nearest cell's class
// draws a staircase (turns of 90 degrees at its corners, up to 0.7 cell from the line), the
// smoothed read a curve (turns of at most ~5 degrees between points a twentieth of a cell apart,
// closer to the line or circle, on the same mean line or radius). Every value read is one of the
// 3 x 3 cells around. By hand: the quadratic B-spline's weights at three points of a 2 x 2 corner,
// with a class and with missing samples (NaN wins as one value), and a lone cell's rounded blob.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/grid.h"
#include "image/layer_sampler.h"
#include "store/store.h"
#include "test_tiles.h"

namespace maquette {
namespace {

constexpr int kLevel = 5, kSize = 64, kFace = 1, kCol0 = 9, kRow0 = 11, kCells = 2;
constexpr uint16_t kNodata = 65535;
// The block's centre, in face pixel coordinates (pixel (c, r)'s centre at (c, r)).
constexpr double kMidCol = kCol0 * kSize + kCells * kSize / 2.0;
constexpr double kMidRow = kRow0 * kSize + kCells * kSize / 2.0;

// A class per face pixel centre.
using Labels = std::function<uint16_t(double col, double row)>;

// A store of categorical layers on kCells x kCells cells of kLevel, one per named shape.
struct Shapes {
  std::string path = (std::filesystem::temp_directory_path() /
                      ("maquette-smooth-labels-" + std::to_string(::getpid()) + ".mqt"))
                         .string();
  explicit Shapes(const std::vector<std::pair<std::string, Labels>>& shapes) {
    const Grid& grid = default_grid();
    std::filesystem::remove(path);
    auto store = Store::open(path, Store::Mode::Create);
    for (const auto& [name, labels] : shapes) {
      LayerInfo l = test::layer_info(name, DType::U16, 1, kSize, kLevel);
      l.semantics = Semantics::Categorical;
      l.nodata = kNodata;
      store->create_layer(l);
      layers.push_back(l);
      Store::Batch batch(*store);
      for (int r = 0; r < kCells; ++r)
        for (int c = 0; c < kCells; ++c) {
          const CellId cell = CellId::FromFaceColRow(kFace, kLevel, kCol0 + c, kRow0 + r);
          batch.put_tile(name, cell,
                         test::make_tile<uint16_t>(grid, cell, kSize, 1,
                                                   [&labels](const test::TileSample& s, int) {
                                                     return labels(double(s.col), double(s.row));
                                                   }));
        }
      batch.commit();
    }
  }
  ~Shapes() {
    for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(path + suffix);
  }
  std::vector<LayerInfo> layers;
};

// The plane point at face pixel coordinates (col, row).
PlanePoint plane_at(double col, double row) {
  const PlaneSquare first =
      default_grid().plane_square(CellId::FromFaceColRow(kFace, kLevel, kCol0, kRow0));
  return {first.x_min + (col + 0.5 - kCol0 * kSize) * first.side / kSize,
          first.y_max - (row + 0.5 - kRow0 * kSize) * first.side / kSize};
}

// Where the class changes from 1 to 2 along the ray from `from` in direction (dx, dy) (a unit
// vector, face pixel coordinates), between `first` and `last` cells along it: the first change
// found in steps of
// a twentieth of a cell, to a thousandth by bisection. Checks every value read is one of the
// 3 x 3 cells around the point's nearest.
double crossing(LayerSampler& sampler, const Labels& labels, std::array<double, 2> from, double dx,
                double dy, double first, double last) {
  auto is_one = [&](double s) {
    const double col = from[0] + s * dx, row = from[1] + s * dy;
    float v = 0;
    EXPECT_TRUE(sampler.sample(plane_at(col, row), &v));
    bool around = false;
    for (int j = -1; j <= 1; ++j)
      for (int i = -1; i <= 1; ++i) around |= labels(std::round(col) + i, std::round(row) + j) == v;
    EXPECT_TRUE(around) << "at " << col << ", " << row << ": " << v;
    return v == 1;
  };
  sampler.start_run();
  double lo = first;
  EXPECT_TRUE(is_one(lo));
  while (lo < last && is_one(lo + 0.05)) lo += 0.05;
  double hi = lo + 0.05;
  EXPECT_LT(lo, last) << "no change along the ray";
  while (hi - lo > 1e-3) (is_one((lo + hi) / 2) ? lo : hi) = (lo + hi) / 2;
  return (lo + hi) / 2;
}

// A boundary's crossings (t along it, s across it, in order of t, at `along` rays a cell): the
// largest distance of one from the straight line (or the constant, `straight` false) fitted to
// them all by least squares, their mean, and the largest turn, in degrees, between successive
// segments of the polyline through them (a staircase turns by up to 90 degrees at its corners, a
// smooth curve a little at each).
struct Wiggle {
  double max = 0, mean = 0, turn = 0;
};
Wiggle wiggle(const std::vector<std::array<double, 2>>& points, const std::vector<double>& t,
              const std::vector<double>& s, bool straight) {
  double st = 0, ss = 0, stt = 0, sts = 0;
  const double n = double(s.size());
  for (size_t i = 0; i < s.size(); ++i)
    st += t[i], ss += s[i], stt += t[i] * t[i], sts += t[i] * s[i];
  const double slope = straight ? (n * sts - st * ss) / (n * stt - st * st) : 0;
  const double offset = (ss - slope * st) / n;
  Wiggle w{0, ss / n, 0};
  for (size_t i = 0; i < s.size(); ++i)
    w.max = std::max(w.max, std::abs(s[i] - offset - slope * t[i]));
  auto heading = [&](size_t i) {
    return std::atan2(points[i + 1][1] - points[i][1], points[i + 1][0] - points[i][0]);
  };
  for (size_t i = 1; i + 1 < points.size(); ++i)
    w.turn = std::max(w.turn,
                      std::abs(std::remainder(heading(i) - heading(i - 1), 2 * M_PI)) * 180 / M_PI);
  return w;
}

TEST(SmoothLabels, AStraightBoundaryIsStraightNotAStaircase) {
  // Class 1 on the pixels whose centre lies on the negative side of a line through a point near
  // the block's centre, at these angles of its normal from the columns' axis.
  const std::array<double, 2> through = {kMidCol + 0.31, kMidRow + 0.17};
  const std::vector<double> angles = {0, 14, 27, 45, 63, 81, 118, 153};
  std::vector<std::pair<std::string, Labels>> shapes;
  for (const double degrees : angles) {
    const double nx = std::cos(degrees * M_PI / 180), ny = std::sin(degrees * M_PI / 180);
    shapes.emplace_back("line" + std::to_string(int(degrees)), [=](double c, double r) {
      return uint16_t(nx * (c - through[0]) + ny * (r - through[1]) < 0 ? 1 : 2);
    });
  }
  const Shapes store_of(shapes);
  const auto store = Store::open(store_of.path, Store::Mode::ReadOnly);
  const Grid& grid = default_grid();
  for (size_t i = 0; i < angles.size(); ++i) {
    SCOPED_TRACE(shapes[i].first);
    const LayerInfo& layer = store_of.layers[i];
    const double nx = std::cos(angles[i] * M_PI / 180), ny = std::sin(angles[i] * M_PI / 180);
    Wiggle w[2];
    for (const auto read : {LayerSampler::Read::kNearest, LayerSampler::Read::kSmoothLabels}) {
      LayerSampler sampler(*store, grid, layer, kLevel, read);
      // Rays along the normal from 3 cells inside, every 0.05 cell along 40 cells of the line.
      std::vector<std::array<double, 2>> points;
      std::vector<double> t, s;
      for (double along = -20; along <= 20; along += 0.05) {
        const std::array<double, 2> from = {through[0] - ny * along, through[1] + nx * along};
        t.push_back(along);
        s.push_back(crossing(sampler, shapes[i].second, from, nx, ny, -3, 3));
        points.push_back({from[0] + s.back() * nx, from[1] + s.back() * ny});
      }
      w[read == LayerSampler::Read::kSmoothLabels] = wiggle(points, t, s, true);
    }
    // The nearest cell's class: a staircase, turning by right angles; smoothed: a curve turning
    // by at most 5.3 degrees a twentieth of a cell, closer to the line, and where the staircase
    // lies on average. An axis-parallel boundary: the cells' edge both ways.
    if (angles[i] == 0) {
      EXPECT_LT(w[1].max, 1e-9);
      EXPECT_EQ(w[1].mean, w[0].mean);
      continue;
    }
    EXPECT_GE(w[0].turn, 80);
    EXPECT_LE(w[1].turn, 8);
    EXPECT_LT(w[1].max, w[0].max * 0.8);
    EXPECT_NEAR(w[1].mean, w[0].mean, 0.01);
  }
}

TEST(SmoothLabels, ADiscIsRoundNotAStaircase) {
  constexpr double kRadius = 6.4;
  const std::array<double, 2> centre = {kMidCol + 0.21, kMidRow - 0.37};
  const Labels disc = [&](double c, double r) {
    return uint16_t(std::hypot(c - centre[0], r - centre[1]) < kRadius ? 1 : 2);
  };
  const Shapes store_of({{"disc", disc}});
  const auto store = Store::open(store_of.path, Store::Mode::ReadOnly);
  Wiggle w[2];
  for (const auto read : {LayerSampler::Read::kNearest, LayerSampler::Read::kSmoothLabels}) {
    LayerSampler sampler(*store, default_grid(), store_of.layers[0], kLevel, read);
    std::vector<std::array<double, 2>> points;
    std::vector<double> t, s;
    for (int k = 0; k < 720; ++k) {
      const double a = k * M_PI / 360;
      t.push_back(a);
      s.push_back(crossing(sampler, disc, centre, std::cos(a), std::sin(a), 0, kRadius + 3));
      points.push_back({centre[0] + s.back() * std::cos(a), centre[1] + s.back() * std::sin(a)});
    }
    w[read == LayerSampler::Read::kSmoothLabels] = wiggle(points, t, s, false);
  }
  // The staircase turns by right angles and strays up to 0.63 cell from its mean radius;
  // smoothed, at most 7.6 degrees a step of half a degree round the centre (0.5 of them the
  // circle's own) and 0.41 cell, its mean radius 6.389 (the staircase's 6.401).
  EXPECT_GE(w[0].turn, 80);
  EXPECT_LE(w[1].turn, 10);
  EXPECT_LT(w[1].max, w[0].max * 0.8);
  EXPECT_NEAR(w[1].mean, kRadius, 0.05);
  EXPECT_NEAR(w[0].mean, kRadius, 0.05);
}

TEST(SmoothLabels, ACornersWeightsByHand) {
  // Class 3 everywhere but the 2 x 2 block's three cells right of, under and diagonal to (c, r):
  // class 5 in one layer, missing (nodata) in the other.
  const double c = kMidCol, r = kMidRow;
  auto corner = [c, r](uint16_t other) {
    return [c, r, other](double col, double row) {
      return uint16_t((col == c + 1 || col == c) && (row == r || row == r + 1) &&
                              !(col == c && row == r)
                          ? other
                          : 3);
    };
  };
  const Shapes store_of({{"five", corner(5)}, {"missing", corner(kNodata)}});
  const auto store = Store::open(store_of.path, Store::Mode::ReadOnly);
  const Grid& grid = default_grid();
  for (const LayerInfo& layer : store_of.layers) {
    SCOPED_TRACE(layer.name);
    LayerSampler nearest(*store, grid, layer, kLevel, LayerSampler::Read::kNearest);
    LayerSampler smooth(*store, grid, layer, kLevel, LayerSampler::Read::kSmoothLabels);
    // The corner's class at (c + d, r + d): 5, or NaN where its cells are missing.
    auto expect_corner = [&](double d) {
      float got = 0;
      ASSERT_TRUE(smooth.sample(plane_at(c + d, r + d), &got));
      if (layer.name == "five")
        EXPECT_EQ(got, 5) << d;
      else
        EXPECT_TRUE(std::isnan(got)) << d;
    };
    float got = 0;
    // At (c + 0.4, r + 0.4) the weights along each axis are 0.005, 0.59, 0.405: the three
    // cells weigh 2 x 0.405 x 0.59 + 0.405^2 = 0.642 against (c, r)'s and the others' 0.358.
    ASSERT_TRUE(nearest.sample(plane_at(c + 0.4, r + 0.4), &got));
    EXPECT_EQ(got, 3);
    expect_corner(0.4);
    // At (c + 0.2, r + 0.2): 0.045, 0.71, 0.245: 2 x 0.245 x 0.71 + 0.245^2 = 0.408, class 3.
    ASSERT_TRUE(smooth.sample(plane_at(c + 0.2, r + 0.2), &got));
    EXPECT_EQ(got, 3);
    // At (c + 0.3, r + 0.3): 0.02, 0.66, 0.32: 0.525 against 0.475.
    expect_corner(0.3);
  }
}

TEST(SmoothLabels, ALoneCellIsARoundedBlobWithinIt) {
  // Class 7 at one cell (c, r), class 3 around it. The cell keeps its class where its weight
  // (3/4 - x^2)(3/4 - y^2) exceeds 1/2: along an axis to 0.289 (3/4 - x^2 > 2/3), along a diagonal
  // to (0.207, 0.207) (3/4 - t^2 > 0.707): a rounded blob between a diamond (0.144 on the
  // diagonal) and a square (0.289). Tent (bilinear) weights would keep (0.25, 0.25): 0.75^2.
  const double c = kMidCol, r = kMidRow;
  const Shapes store_of({{"lone", [c, r](double col, double row) {
                            return uint16_t(col == c && row == r ? 7 : 3);
                          }}});
  const auto store = Store::open(store_of.path, Store::Mode::ReadOnly);
  LayerSampler smooth(*store, default_grid(), store_of.layers[0], kLevel,
                      LayerSampler::Read::kSmoothLabels);
  const std::vector<std::array<double, 3>> expected = {
      {0, 0, 7},     {0.28, 0, 7},    {0.30, 0, 3},   {0, -0.28, 7},    {0, -0.30, 3},
      {0.2, 0.2, 7}, {0.25, 0.25, 3}, {-0.2, 0.2, 7}, {-0.22, -0.22, 3}};
  for (const auto& [dx, dy, want] : expected) {
    float got = 0;
    ASSERT_TRUE(smooth.sample(plane_at(c + dx, r + dy), &got));
    EXPECT_EQ(got, want) << dx << ", " << dy;
  }
}

}  // namespace
}  // namespace maquette
