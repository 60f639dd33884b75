// Horizon angles against the closed form atan((H - d^2 / 2R) / d) of terrain of height H at
// distance d, on a flat DEM of 70 m pixels: a wall one pixel thin, or a pillar one pixel wide on
// an oblique march, is found at any distance, also where the march samples only every 2nd, 4th,
// ... pixel (the samples read maxima over squares around them), up to half a spacing before the
// edge of the halo, where the march ends; a march along a path of data between voids goes on.
#include "../horizon.h"

#include <gtest/gtest.h>

#include <cmath>

namespace maquette::climate {
namespace {

constexpr int kSize = 64, kHalo = 64;
constexpr double kPixel = 70;

PixelFrame east_south_frame() {
  PixelFrame frame;  // columns run east, rows south
  frame.col = {kPixel, 0};
  frame.row = {0, -kPixel};
  frame.valid = true;
  return frame;
}

double angle(double height, double distance) {
  return std::atan((height - distance * distance / (2 * kEarthRadius)) / distance);
}

TEST(Horizon, ThinWallsAreFoundAtAnyDistance) {
  const int B = HorizonAngles::kBlock;
  const PixelFrame frame = east_south_frame();
  // The block at column 0 looks east (azimuth 90: direction 1 of 4) at a wall of height 500 m
  // one column thin, at every column from B + 1 to kSize + kHalo - 2 in turn.
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
      const double got = angles[size_t(B / 2 * B + col) * 4 + 1];
      ASSERT_LE(got, angle(500, d - slack) + 1e-6)
          << "wall at column " << wall << ", pixel " << col;
      ASSERT_GE(got, angle(500, d + slack) - 1e-6)
          << "wall at column " << wall << ", pixel " << col;
    }
  }
  EXPECT_GT(far_walls, 1000);
}

// Between two far samples 2^l pixels apart an oblique march also moves up to 2^l pixels across:
// a pillar one pixel wide on the path of the centre pixel of the block at (32, 32), at azimuths
// 30, 45, 120 and 225 degrees (of 24 directions) and distances of 17 to 250 steps.
TEST(Horizon, ThinPillarsAreFoundOnObliqueMarches) {
  constexpr int kWideHalo = 256, kCol0 = 32, kRow0 = 32, kCentre = 32 + HorizonAngles::kBlock / 2;
  const PixelFrame frame = east_south_frame();
  const HorizonAngles horizons(24, 1e6);
  for (const int k : {2, 3, 8, 15}) {
    std::vector<char> used(24, 0);
    used[size_t(k)] = 1;
    const double azimuth = k * 15 * M_PI / 180;
    const double east = std::sin(azimuth), south = -std::cos(azimuth);
    const double longest = std::max(std::abs(east), std::abs(south));
    for (int step = HorizonAngles::kFineSteps + 1; step <= 250; step += 7) {
      const int dc = int(std::lround(step * east / longest));
      const int dr = int(std::lround(step * south / longest));
      Tile<float> dem(64, 1, kWideHalo, 0.f);
      dem.at(kCentre + dc, kCentre + dr) = 500;
      const DilatedDem surfaces(dem, HorizonAngles::kLevels);
      std::vector<float> angles;
      horizons.compute(surfaces, 500, used, frame, kCol0, kRow0, angles);
      // Seen from the sample nearest along the march: at most half a spacing (step / 15) and
      // two pixels nearer or farther.
      const double d = kPixel * std::hypot(dc, dr);
      const double slack = (step / 15.0 + 2) * kPixel / longest;
      const int centre = HorizonAngles::kBlock / 2 * (HorizonAngles::kBlock + 1);
      const double got = angles[size_t(centre) * 24 + size_t(k)];
      ASSERT_LE(got, angle(500, d - slack) + 1e-6) << "azimuth " << k * 15 << ", step " << step;
      ASSERT_GE(got, angle(500, d + slack) - 1e-6) << "azimuth " << k * 15 << ", step " << step;
    }
  }
}

// A march along a row, a column or a diagonal interpolates with weight 0 (or 1) across it: the
// pixels beside its path are not read, so voids there do not end it. Only the path of the block's
// centre pixel has data, with a 500 m pillar 12 steps out.
TEST(Horizon, VoidsBesideAPathDoNotEndTheMarch) {
  const int B = HorizonAngles::kBlock, centre = B / 2 * (B + 1);
  const PixelFrame frame = east_south_frame();
  const HorizonAngles horizons(8, 1e6);
  for (const int k : {0, 1, 2, 5}) {  // azimuths 0, 45, 90, 225
    std::vector<char> used(8, 0);
    used[size_t(k)] = 1;
    const int east = k == 0 ? 0 : k == 5 ? -1 : 1, south = k == 0 || k == 1 ? -1 : k == 5 ? 1 : 0;
    Tile<float> dem(kSize, 1, kHalo, NAN);
    for (int step = 0; step <= 40; ++step) dem.at(B / 2 + east * step, B / 2 + south * step) = 0;
    dem.at(B / 2 + east * 12, B / 2 + south * 12) = 500;
    const DilatedDem surfaces(dem, HorizonAngles::kLevels);
    std::vector<float> angles;
    horizons.compute(surfaces, 500, used, frame, 0, 0, angles);
    const double d = 12 * kPixel * std::hypot(east, south);
    EXPECT_NEAR(angles[size_t(centre) * 8 + size_t(k)], angle(500, d), 1e-5)
        << "azimuth " << k * 45;
  }
}

}  // namespace
}  // namespace maquette::climate
