// lake_columns (water_columns.h) on the analytic paraboloid basin: a column per wet pixel, none
// for a dry one, each holding the voxels whose centres lie between the surface and the bed
// (counted here from the depth), at the pixel's centre on the lattice; their volume the
// paraboloid's closed form within 0.5 % and the body's to a voxel's rounding.
#include "water_columns.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "water_basins.h"

namespace maquette::deform {
namespace {

TEST(WaterColumns, ParaboloidColumnsHoldTheDepthAtEachWetPixel) {
  const Basin b = paraboloid();
  const BasinRaster raster = b.raster();
  const WaterBody body = fill_basin(raster, water_level(raster, {}));
  ASSERT_GT(body.wet.size(), 100000u);
  // Pixel (col, row)'s centre at (col + 1/2, -(row + 1/2)) metres.
  const int64_t seed_col = body.seed % b.width, seed_row = body.seed / b.width;
  const auto centre = [&](int64_t col, int64_t row) {
    return std::array{double(col) + 0.5, -(double(row) + 0.5), body.level};
  };
  const PixelLattice lattice{centre(seed_col, seed_row), {1, 0, 0}, {0, -1, 0}};
  std::vector<std::array<double, 3>> surface;
  for (const int64_t w : body.wet) surface.push_back(centre(w % b.width, w / b.width));
  const FogColumns fog = lake_columns(raster, body, lattice, surface, 32);
  const float deepest = *std::max_element(body.depth.begin(), body.depth.end());
  const double dz = double(deepest) / 32;
  EXPECT_EQ(fog.axes[2][2], dz);
  std::vector<uint8_t> wet(size_t(b.width) * size_t(b.height), 0);
  for (const int64_t w : body.wet) wet[size_t(w)] = 1;
  double voxels = 0;
  size_t columns = 0, wrong = 0, misplaced = 0;
  size_t w = 0;  // the wet pixels in row-major order
  for (int64_t row = 0; row < b.height; ++row)
    for (int64_t col = 0; col < b.width; ++col) {
      if (!wet[size_t(row * b.width + col)]) continue;
      // Its column: where the lattice puts its centre.
      const double x = double(col) + 0.5, y = -(double(row) + 0.5);
      const double i = (x - fog.centre[0]) / fog.axes[0][0];
      const double j = (y - fog.centre[1]) / fog.axes[1][1];
      misplaced += std::abs(i - std::round(i)) > 1e-9 || std::abs(j - std::round(j)) > 1e-9;
      const size_t at = size_t(std::round(j)) * size_t(fog.width) + size_t(std::round(i));
      // The voxels below the surface whose centres lie above the bed, counted from the depth.
      const double depth = double(body.depth[w++]);
      int count = 0;
      while ((count + 0.5) * dz < depth) ++count;
      const int held = std::max(0, fog.high[at] - fog.low[at]);
      wrong += held != count || (count > 0 && fog.high[at] != 0);
      columns += held > 0;
      voxels += held;
    }
  EXPECT_EQ(misplaced, 0u);
  EXPECT_EQ(wrong, 0u);
  // Every column with voxels is a wet pixel's.
  size_t filled = 0;
  for (size_t c = 0; c < fog.low.size(); ++c) filled += fog.low[c] < fog.high[c];
  EXPECT_EQ(filled, columns);
  // All but the rim shallower than half a voxel (3.2 m).
  EXPECT_GT(columns, body.wet.size() * 98 / 100);
  const double level = body.level, volume = voxels * dz * raster.pixel_area_m2;
  EXPECT_NEAR(volume, std::numbers::pi * 1000 * level * level / 2,
              0.005 * std::numbers::pi * 1000 * level * level / 2);
  EXPECT_NEAR(volume, body.volume_m3, 0.001 * body.volume_m3);
}

}  // namespace
}  // namespace maquette::deform
