// The inputs at the target resolution (field.h): the upsampled plane is the cubic B-spline of the
// input at every target pixel centre, and positions along a row are those of single pixels, bit
// for bit.
#include "../field.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <vector>

namespace maquette::texture {
namespace {

// The uniform cubic B-spline kernel at distance d from a control point.
double bspline(double d) {
  d = std::abs(d);
  return d < 1 ? (4 - 6 * d * d + 3 * d * d * d) / 6 : d < 2 ? (2 - d) * (2 - d) * (2 - d) / 6 : 0;
}

// An input of rough values (every tap shows), refined 1 to 3 levels: every target pixel, ring
// included, is the kernel-weighted sum of the input pixels around its centre.
TEST(Upsample, CubicBSplineAtTheTargetPixels) {
  constexpr int kSize = 8, kRing = 2;
  Tile<float> in(kSize, 1, kInputHalo);
  for (int r = -kInputHalo; r < kSize + kInputHalo; ++r)
    for (int c = -kInputHalo; c < kSize + kInputHalo; ++c)
      in.at(c, r) = float(100 * std::sin(1.3 * c + 0.7 * r * r) + c * r);
  for (const int refine : {1, 2, 3}) {
    const Plane p = upsample(in, refine, kRing);
    const double scale = 1 << refine;
    for (int r = -kRing; r < p.size + kRing; ++r)
      for (int c = -kRing; c < p.size + kRing; ++c) {
        const double u = (c + 0.5) / scale - 0.5, v = (r + 0.5) / scale - 0.5;
        double expected = 0;
        for (int j = int(std::floor(v)) - 2; j <= int(std::floor(v)) + 3; ++j)
          for (int i = int(std::floor(u)) - 2; i <= int(std::floor(u)) + 3; ++i)
            expected += bspline(u - i) * bspline(v - j) * in.at(i, j);
        ASSERT_NEAR(p.at(c, r), expected, 1e-3) << refine << " " << c << " " << r;
      }
  }
}

// At 8.8 m (lattice of every 32nd pixel) and 140 m pixels (every 8th): every step the noise
// uses, runs starting anywhere and crossing lattice cells; the same from the kept rows.
TEST(PixelPositions, AlongRowSameBitsAsAt) {
  constexpr int kSize = 64, kRing = 25;
  for (const CellId cell :
       {CellId::FromFaceColRow(2, 14, 7700, 8100), CellId::FromFaceColRow(2, 10, 481, 506)}) {
    const PixelPositions position(default_grid(), cell, kSize, 0, kRing);
    for (int r = -kRing; r < kSize + kRing; r += 3)
      for (const int step : {1, 2, 4, 8})
        for (int c0 = -kRing; c0 < kSize + kRing; c0 += 7) {
          const int n = std::min(40, (kSize + kRing - 1 - c0) / step + 1);
          Points row;
          row.resize(size_t(n));
          position.along_row(c0, step, n, r, row.to(0));
          // Kept rows: first computed, then found again (the second request inside the first).
          const Coordinates kept = position.along_row_kept(c0, step, n, r),
                            again = position.along_row_kept(c0 + step, step, n - 1, r);
          for (int k = 0; k < n; ++k)
            for (size_t a = 0; a < 3; ++a) {
              const uint64_t expected = std::bit_cast<uint64_t>(position.at(c0 + k * step, r)[a]);
              ASSERT_EQ(std::bit_cast<uint64_t>(row.axis[a][size_t(k)]), expected)
                  << cell.ToText() << " row " << r << " col " << c0 + k * step;
              ASSERT_EQ(std::bit_cast<uint64_t>(kept[a][k]), expected) << "kept";
              if (k > 0) {
                ASSERT_EQ(std::bit_cast<uint64_t>(again[a][k - 1]), expected) << "again";
              }
            }
        }
  }
}

}  // namespace
}  // namespace maquette::texture
