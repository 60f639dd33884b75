// The nearest, bilinear and cubic kernels (four samples at a time where the CPU has AVX2, one by
// one otherwise and for the last samples) against their definitions: the pixel holding the
// point; the 2 x 2 pixels around it, weights renormalised over the valid ones, NaN when none;
// Keys' cubic convolution (a = -0.5) over the 4 x 4 around it, bilinear where one is missing.
// And the same bits whichever way a sample is computed.
#include "gdal/resample.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace maquette::test {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// A window of 2 bands with about one pixel in `holes` missing.
Window test_window(int w, int h, int step, int holes) {
  Window win;
  win.x0 = 100;
  win.y0 = 50;
  win.w = w;
  win.h = h;
  win.step = step;
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> value(-500, 3000);
  for (int b = 0; b < 2; ++b) {
    std::vector<float> plane(size_t(w) * size_t(h));
    for (float& v : plane) v = rng() % holes == 0 ? kNaN : value(rng);
    win.planes.push_back(std::move(plane));
  }
  return win;
}

// The definitions, in double, from source pixel coordinates.
float expected_nearest(const Window& w, int band, double x, double y) {
  return w.at(band, int(std::floor((x - double(w.x0)) / w.step)),
              int(std::floor((y - double(w.y0)) / w.step)));
}

float expected_bilinear(const Window& w, int band, double x, double y) {
  const double u = (x - double(w.x0)) / w.step - 0.5, v = (y - double(w.y0)) / w.step - 0.5;
  const double i = std::floor(u), j = std::floor(v), fu = u - i, fv = v - j;
  double sum = 0, norm = 0;
  for (int dj = 0; dj < 2; ++dj)
    for (int di = 0; di < 2; ++di) {
      const float s = w.at(band, int(i) + di, int(j) + dj);
      const double weight = (di ? fu : 1 - fu) * (dj ? fv : 1 - fv);
      if (!std::isnan(s) && weight > 0) {
        sum += weight * s;
        norm += weight;
      }
    }
  return norm > 0 ? float(sum / norm) : kNaN;
}

// Keys' kernel at distance d (a = -0.5).
double keys_weight(double d) {
  constexpr double a = -0.5;
  d = std::abs(d);
  if (d <= 1) return (a + 2) * d * d * d - (a + 3) * d * d + 1;
  if (d < 2) return a * d * d * d - 5 * a * d * d + 8 * a * d - 4 * a;
  return 0;
}

float expected_cubic(const Window& w, int band, double x, double y) {
  const double u = (x - double(w.x0)) / w.step - 0.5, v = (y - double(w.y0)) / w.step - 0.5;
  const int i = int(std::floor(u)), j = int(std::floor(v));
  double sum = 0;
  for (int dj = -1; dj <= 2; ++dj)
    for (int di = -1; di <= 2; ++di) {
      const float s = w.at(band, i + di, j + dj);
      if (std::isnan(s)) return expected_bilinear(w, band, x, y);
      sum += keys_weight(u - (i + di)) * keys_weight(v - (j + dj)) * s;
    }
  return float(sum);
}

struct Points {
  std::vector<double> x, y;
};

// Points over the window and a pixel beyond each edge, some not to be resampled (x NaN).
Points test_points(const Window& w, size_t n) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> px(double(w.x0) - w.step,
                                            double(w.x0) + (w.w + 1) * w.step);
  std::uniform_real_distribution<double> py(double(w.y0) - w.step,
                                            double(w.y0) + (w.h + 1) * w.step);
  Points p;
  for (size_t i = 0; i < n; ++i) {
    p.x.push_back(i % 13 == 5 ? std::numeric_limits<double>::quiet_NaN() : px(rng));
    p.y.push_back(py(rng));
  }
  return p;
}

void expect_definition(Resampling r, int step) {
  const Window w = test_window(40, 30, step, 9);
  const Points p = test_points(w, 4003);  // not a multiple of 4: the last ones one by one
  std::vector<float> out(p.x.size() * 2, kNaN);
  out[6] = 42;  // already filled by an earlier source: kept
  resample(w, r, {p.x, p.y, {}, {}}, out);
  int nan = 0, valid = 0;
  for (size_t i = 0; i < p.x.size(); ++i)
    for (int b = 0; b < 2; ++b) {
      const float got = out[i * 2 + size_t(b)];
      if (i * 2 + size_t(b) == 6) {
        EXPECT_EQ(got, 42);
        continue;
      }
      if (std::isnan(p.x[i])) {
        EXPECT_TRUE(std::isnan(got)) << i;
        continue;
      }
      const float want = r == Resampling::Nearest ? expected_nearest(w, b, p.x[i], p.y[i])
                         : r == Resampling::Cubic ? expected_cubic(w, b, p.x[i], p.y[i])
                                                  : expected_bilinear(w, b, p.x[i], p.y[i]);
      if (std::isnan(want)) {
        EXPECT_TRUE(std::isnan(got)) << "sample " << i << " band " << b;
        ++nan;
      } else {
        EXPECT_NEAR(got, want, 1e-6 * std::abs(want) + 1e-6) << "sample " << i << " band " << b;
        ++valid;
      }
    }
  EXPECT_GT(nan, 50);  // outside the window and missing pixels
  EXPECT_GT(valid, 5000);
}

TEST(ResampleNearest, MatchesTheDefinition) { expect_definition(Resampling::Nearest, 1); }

TEST(ResampleNearest, MatchesTheDefinitionOnACoarserWindow) {
  expect_definition(Resampling::Nearest, 3);
}

TEST(ResampleBilinear, MatchesTheDefinition) { expect_definition(Resampling::Bilinear, 1); }

TEST(ResampleBilinear, MatchesTheDefinitionOnACoarserWindow) {
  expect_definition(Resampling::Bilinear, 3);
}

TEST(ResampleCubic, MatchesTheDefinition) { expect_definition(Resampling::Cubic, 1); }

TEST(ResampleCubic, MatchesTheDefinitionOnACoarserWindow) {
  expect_definition(Resampling::Cubic, 3);
}

// Each sample alone (fewer than four: the one-by-one path) gives the bits the whole array gives.
void expect_same_bits(Resampling r) {
  for (const int step : {1, 2}) {
    const Window w = test_window(25, 20, step, 5);
    const Points p = test_points(w, 1000);
    std::vector<float> all(p.x.size() * 2, kNaN);
    resample(w, r, {p.x, p.y, {}, {}}, all);
    for (size_t i = 0; i < p.x.size(); ++i) {
      float one[2] = {kNaN, kNaN};
      resample(w, r, {std::span(p.x).subspan(i, 1), std::span(p.y).subspan(i, 1), {}, {}}, one);
      EXPECT_EQ(std::memcmp(one, &all[i * 2], sizeof one), 0) << "sample " << i;
    }
  }
}

TEST(ResampleNearest, SameBitsOneByOneAsFourAtATime) { expect_same_bits(Resampling::Nearest); }

TEST(ResampleBilinear, SameBitsOneByOneAsFourAtATime) { expect_same_bits(Resampling::Bilinear); }

TEST(ResampleCubic, SameBitsOneByOneAsFourAtATime) { expect_same_bits(Resampling::Cubic); }

}  // namespace
}  // namespace maquette::test
