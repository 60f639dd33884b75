// The clone brush's slope-aware resize (issue 20's oracle): a checkerboard draped on a two-slope
// terrain (flat, then a 30 degree slope), seen from above, cloned from the flat part onto the
// slope: measured in ground metres through the heights, the cloned squares keep the source's
// ground area (the cosine prediction: seen from above they are cos 30 as large). The slope under a
// region against the plane it was built from; bad input named.
#include "../terrain_slope.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "../clone.h"
#include "../patchmatch.h"
#include "core/error.h"
#include "synthetic_images.h"

namespace maquette::synthesis {
namespace {

constexpr int kW = 200, kH = 120, kCrease = 100, kSquare = 12;
constexpr double kSpacing = 10, kSlopeDeg = 30;
const double kTan = std::tan(kSlopeDeg * std::numbers::pi / 180);

// Flat west of the crease, rising east at 30 degrees beyond it.
double ground_height(double x) { return x <= kCrease ? 0 : (x - kCrease) * kSpacing * kTan; }

std::vector<float> two_slopes() {
  std::vector<float> heights(size_t(kW) * kH);
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) heights[size_t(y) * kW + x] = float(ground_height(x));
  }
  return heights;
}

// Where the first channel crosses 120 (between the squares' 40 and 200), linearly interpolated
// between samples, along x on row `y` (or along y on column `x`) from `from` to `to`.
std::vector<double> crossings(const PatchImage& image, bool along_x, int line, int from, int to) {
  const auto value = [&](int i) {
    return along_x ? image.pixel(i, line)[0] : image.pixel(line, i)[0];
  };
  std::vector<double> out;
  for (int i = from; i < to; ++i) {
    const double a = value(i) - 120.0, b = value(i + 1) - 120.0;
    if ((a < 0) != (b < 0)) out.push_back(i + a / (a - b));
  }
  return out;
}

TEST(TerrainSlope, ACheckerboardClonedFromFlatGroundOntoA30DegreeSlopeKeepsItsGroundArea) {
  PatchImage image(kW, kH, 3);
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      std::fill_n(image.pixel(x, y), 3, ((x / kSquare + y / kSquare) % 2) != 0 ? 200.0f : 40.0f);
    }
  }
  const std::vector<float> heights = two_slopes();
  // 48 x 48 at (12, 36), its centre (35.5, 59.5) moved to (155.5, 59.5), on the slope.
  const auto source = test::square_mask(kW, kH, 12, 36, 48);
  CloneParams params;
  params.offset_x = 120;
  const SampleFrame frame{{kSpacing, 0}, {0, kSpacing}};
  const GroundSlope from =
      ground_slope(region_gradient(heights, kW, kH, source, 0, 0, "source"), frame);
  const GroundSlope to =
      ground_slope(region_gradient(heights, kW, kH, source, 120, 0, "destination"), frame);
  EXPECT_NEAR(from.slope_deg, 0, 1e-9);
  EXPECT_NEAR(to.slope_deg, kSlopeDeg, 1e-4);
  EXPECT_NEAR(to.aspect_deg, 0, 1e-9);
  params.linear = slope_resize(from, frame, to, frame);
  const PatchImage out = clone(image, source, params, PatchMatch());

  // Along the slope: the destination spans 155.5 +- 24 cos 30 = 134.7..176.3; inside its band.
  const int band = params.fill.band + 1;
  const auto xs = crossings(out, true, 60, 135 + band, 176 - band);
  // Across it (no resize): rows 36..83.
  const auto ys = crossings(out, false, 155, 36 + band, 83 - band);
  ASSERT_GE(xs.size(), 3u);
  ASSERT_GE(ys.size(), 3u);
  const double image_width = (xs.back() - xs.front()) / double(xs.size() - 1);
  const double image_height = (ys.back() - ys.front()) / double(ys.size() - 1);
  // Ground lengths through the heights: along the row the ground rises with x.
  const double ground_width = std::hypot((xs.back() - xs.front()) * kSpacing,
                                         ground_height(xs.back()) - ground_height(xs.front())) /
                              double(xs.size() - 1);
  const double ground_height_m = image_height * kSpacing;
  const double source_area = kSquare * kSquare * kSpacing * kSpacing;
  const double cosine = std::cos(kSlopeDeg * std::numbers::pi / 180);
  EXPECT_NEAR(ground_width * ground_height_m / source_area, 1, 0.02)
      << ground_width << " x " << ground_height_m << " m";
  EXPECT_NEAR(image_width * image_height / (kSquare * kSquare * cosine), 1, 0.02)
      << image_width << " x " << image_height << " samples";
}

TEST(TerrainSlope, ARegionOnAPlaneHasItsSlopeAndAspectOnTheGround) {
  // z = 3 x - 4 y (in samples of 2 m): gradient (1.5, -2) per metre, |g| = 2.5.
  constexpr int kSide = 20;
  std::vector<float> heights(kSide * kSide);
  for (int y = 0; y < kSide; ++y) {
    for (int x = 0; x < kSide; ++x) heights[size_t(y) * kSide + x] = float(3 * x - 4 * y);
  }
  const auto region = test::square_mask(kSide, kSide, 4, 4, 6);
  const GroundSlope s = ground_slope(region_gradient(heights, kSide, kSide, region, 0, 0, "region"),
                                     SampleFrame{{2, 0}, {0, 2}});
  EXPECT_NEAR(s.slope_deg, std::atan(2.5) * 180 / std::numbers::pi, 1e-9);
  EXPECT_NEAR(s.aspect_deg, std::atan2(-2, 1.5) * 180 / std::numbers::pi, 1e-9);
}

TEST(TerrainSlope, OnSamplesLongerEastThanSouthTheResizeIsInGroundMetres) {
  // rHEALPix's samples at the equator (38 m east by 32 m south at level 18), and a destination
  // whose 30 degree slope falls towards the south-east on the ground.
  const SampleFrame frame{{38, 0}, {0, 32}};
  const GroundSlope flat{0, 0}, slope{30, 45};
  const auto m = slope_resize(flat, frame, slope, frame);
  // A sample offset's ground vector after the map: along the slope's direction times cos 30,
  // across it kept.
  const auto ground_after = [&](double col, double row) {
    return std::array<double, 2>{38 * (m[0] * col + m[1] * row), 32 * (m[2] * col + m[3] * row)};
  };
  const double cosine = std::cos(kSlopeDeg * std::numbers::pi / 180);
  const auto along = ground_after(1 / 38.0, 1 / 32.0);    // 1 m east and 1 m south
  const auto across = ground_after(1 / 38.0, -1 / 32.0);  // 1 m east and 1 m north
  EXPECT_NEAR(along[0], cosine, 1e-12);
  EXPECT_NEAR(along[1], cosine, 1e-12);
  EXPECT_NEAR(across[0], 1, 1e-12);
  EXPECT_NEAR(across[1], -1, 1e-12);
  // The same heights seen through the frame: 1 m per sample east is a gradient of 1/38.
  const GroundSlope east = ground_slope({1, 0}, frame);
  EXPECT_NEAR(east.slope_deg, std::atan(1 / 38.0) * 180 / std::numbers::pi, 1e-12);
  EXPECT_NEAR(east.aspect_deg, 0, 1e-12);
}

TEST(TerrainSlope, ARegionWithoutKnownHeightsIsNamed) {
  const std::vector<float> heights(100, NAN);
  try {
    region_gradient(heights, 10, 10, test::square_mask(10, 10, 2, 2, 4), 0, 0, "inputs.dem");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "inputs.dem: no known heights under the region");
  }
}

}  // namespace
}  // namespace maquette::synthesis
