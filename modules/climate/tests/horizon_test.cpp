// Horizon angles against the closed form atan((H - d^2 / 2R) / d) of a wall of height H at
// distance d, on a flat DEM of 70 m pixels: a wall one pixel thin is found at any distance,
// also where the march samples only every 2nd, 4th, ... pixel (the samples read the running
// maxima over their spacing), up to half a spacing before the edge of the halo, where the
// march ends.
#include "../horizon.h"

#include <gtest/gtest.h>

#include <cmath>

namespace maquette::climate {
namespace {

constexpr int kSize = 64, kHalo = 64;
constexpr double kPixel = 70;

TEST(Horizon, ThinWallsAreFoundAtAnyDistance) {
  const int B = HorizonAngles::kBlock;
  PixelFrame frame;  // columns run east, rows south
  frame.col = {kPixel, 0};
  frame.row = {0, -kPixel};
  frame.valid = true;
  // The block at column 0 looks east (azimuth 90: direction 1 of 4) at a wall of height 500 m
  // one column thin, at every column from 2 to kSize + kHalo - 2 in turn.
  const HorizonAngles horizons(4, 1e6);
  const std::vector<char> used = {0, 1, 0, 0};
  int far_walls = 0;
  for (int wall = B + 1; wall < kSize + kHalo - 1; ++wall) {
    Tile<float> dem(kSize, 1, kHalo, 0.f);
    for (int row = -kHalo; row < kSize + kHalo; ++row) dem.at(wall, row) = 500;
    const DilatedDem surfaces(dem, HorizonAngles::kLevels);
    std::vector<float> angles;
    horizons.compute(surfaces, 500, used, frame, 0, 0, angles);
    for (int col = 0; col < B; ++col) {
      const double d = (wall - col) * kPixel;
      // Samples every 2^l pixels beyond 2^(l-1) kFineSteps: the wall is seen from at most half
      // a spacing, d / kFineSteps, nearer or farther.
      const double slack = d / HorizonAngles::kFineSteps;
      if (wall + slack / kPixel > kSize + kHalo - 2) continue;
      if (d > HorizonAngles::kFineSteps * kPixel) ++far_walls;
      const auto angle = [](double distance) {
        return std::atan((500 - distance * distance / (2 * kEarthRadius)) / distance);
      };
      const double got = angles[size_t(B / 2 * B + col) * 4 + 1];
      ASSERT_LE(got, angle(d - slack) + 1e-6) << "wall at column " << wall << ", pixel " << col;
      ASSERT_GE(got, angle(d + slack) - 1e-6) << "wall at column " << wall << ", pixel " << col;
    }
  }
  EXPECT_GT(far_walls, 1000);
}

}  // namespace
}  // namespace maquette::climate
