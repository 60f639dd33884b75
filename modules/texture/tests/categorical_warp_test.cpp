// The warped nearest neighbour of categorical rasters (categorical_warp.h): the warp is bounded,
// smooth and not trivial; a target pixel reads the input pixel under its warped centre, the same
// for any tiling; class borders no longer follow the input pixels' edges.
#include "../categorical_warp.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

namespace maquette::texture {
namespace {

// Every 16th of an input pixel over 24 x 24 input pixels far from the origin: within the bound,
// steps between neighbouring samples within the warp's largest slope times the step (per octave
// fade' <= 1.875 times node differences <= 2 times amplitude / spacing, 0.9375 per input pixel
// for each of the two), and a spread that displaces borders visibly.
TEST(CategoricalWarp, BoundedSmoothAndNotTrivial) {
  constexpr double kStep = 1.0 / 16, kX0 = 123456, kY0 = 654321;
  constexpr int kN = 24 * 16;
  const double max_step = 2 * 0.9375 * kStep;
  double sum = 0, sum2 = 0;
  for (int j = 0; j < kN; ++j)
    for (int i = 0; i < kN; ++i) {
      const double x = kX0 + i * kStep, y = kY0 + j * kStep;
      const auto d = categorical_warp(x, y), right = categorical_warp(x + kStep, y),
                 below = categorical_warp(x, y + kStep);
      for (int a = 0; a < 2; ++a) {
        ASSERT_LE(std::abs(d[a]), kMaxCategoricalWarp) << x << " " << y;
        ASSERT_LE(std::abs(right[a] - d[a]), max_step) << x << " " << y;
        ASSERT_LE(std::abs(below[a] - d[a]), max_step) << x << " " << y;
      }
      sum += d[0], sum2 += d[0] * d[0];
    }
  const double n = double(kN) * kN, mean = sum / n;
  EXPECT_LT(std::abs(mean), 0.1);
  EXPECT_GT(std::sqrt(sum2 / n - mean * mean), 0.15);
}

// Distinct codes per global input pixel, read two levels finer as one tile of 16 input pixels and
// as its four quarters: the same code at every target pixel, and that code is the input pixel's
// under the warped centre (never more than one input pixel away from the pixel it lies in).
TEST(CategoricalWarp, SamePixelsForAnyTiling) {
  constexpr int kSize = 16, kRefine = 2, kRing = 1;
  constexpr int64_t kCol0 = 40000, kRow0 = 52000;
  const auto code = [](int64_t c, int64_t r) { return float((c * 7 + r * 13) % 256); };
  const auto input = [&](int size, int64_t col0, int64_t row0) {
    Tile<float> t(size, 1, kInputHalo);
    for (int r = -kInputHalo; r < size + kInputHalo; ++r)
      for (int c = -kInputHalo; c < size + kInputHalo; ++c) t.at(c, r) = code(col0 + c, row0 + r);
    return t;
  };
  Plane whole;
  nearest_warped(input(kSize, kCol0, kRow0), kCol0, kRow0, kRefine, kRing, whole);
  const int m = kSize << kRefine;
  int moved = 0;
  for (int r = -kRing; r < m + kRing; ++r)
    for (int c = -kRing; c < m + kRing; ++c) {
      const double x = kCol0 + (c + 0.5) / 4, y = kRow0 + (r + 0.5) / 4;
      const auto [dx, dy] = categorical_warp(x, y);
      const int64_t ic = int64_t(std::floor(x + dx)), ir = int64_t(std::floor(y + dy));
      ASSERT_EQ(whole.at(c, r), code(ic, ir)) << c << " " << r;
      ASSERT_LE(std::abs(ic - int64_t(std::floor(x))), 1);
      ASSERT_LE(std::abs(ir - int64_t(std::floor(y))), 1);
      moved += ic != int64_t(std::floor(x)) || ir != int64_t(std::floor(y));
    }
  EXPECT_GT(moved, m * m / 5) << "borders should move off the input pixels' edges";
  for (const int qr : {0, 1})
    for (const int qc : {0, 1}) {
      const int64_t col0 = kCol0 + qc * kSize / 2, row0 = kRow0 + qr * kSize / 2;
      Plane quarter;
      nearest_warped(input(kSize / 2, col0, row0), col0, row0, kRefine, kRing, quarter);
      for (int r = -kRing; r < m / 2 + kRing; ++r)
        for (int c = -kRing; c < m / 2 + kRing; ++c)
          ASSERT_EQ(quarter.at(c, r), whole.at(c + qc * m / 2, r + qr * m / 2)) << c << " " << r;
    }
}

}  // namespace
}  // namespace maquette::texture
