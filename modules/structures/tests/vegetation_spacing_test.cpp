// estimate_spacing (spacing_estimate.h) on synthetic orthophotos of crowns (dark green discs with
// soft edges on bright ground, with pixel noise) at a known spacing: square lattices turned by an
// angle, jittered, and seen through a polygon mask, each within +-10 %; the rings of four tiles
// summed (as structures.vegetation_spacing sums a stroke's tiles); a strong brightness gradient
// over the crowns; a gradient alone, a uniform image and images too small refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "../spacing_estimate.h"
#include "core/splitmix64.h"

namespace maquette::structures {
namespace {

struct Scene {
  double spacing_m, angle_deg, jitter;  // jitter: of the spacing, each crown moved up to it
  bool masked;                          // a disc of the image only (NaN beyond)
};

// A width x width luminance image of pixels px x py metres (x east, y south): crowns of radius
// 0.35 spacing.
std::vector<float> orthophoto(const Scene& s, int width, double px, double py) {
  const double t = s.angle_deg * std::numbers::pi / 180, radius = 0.35 * s.spacing_m;
  uint64_t state = 42;
  const auto unit = [&] { return unit_interval(splitmix64_next(state)); };
  std::vector<float> image(size_t(width) * size_t(width));
  const double extent_x = width * px, extent_y = width * py;
  const int n = int(std::max(extent_x, extent_y) * 1.5 / s.spacing_m) + 2;
  std::vector<std::pair<double, double>> crowns;
  for (int j = -n; j <= n; ++j)
    for (int i = -n; i <= n; ++i) {
      const double u = (i + s.jitter * (2 * unit() - 1)) * s.spacing_m;
      const double v = (j + s.jitter * (2 * unit() - 1)) * s.spacing_m;
      crowns.push_back({extent_x / 2 + u * std::cos(t) - v * std::sin(t),
                        extent_y / 2 + u * std::sin(t) + v * std::cos(t)});
    }
  std::vector<double> crown(image.size(), 0);  // cover of each pixel, soft at the rims
  for (const auto& [cx, cy] : crowns) {
    const int c0 = std::max(0, int((cx - radius) / px) - 1);
    const int c1 = std::min(width - 1, int((cx + radius) / px) + 1);
    const int r0 = std::max(0, int((cy - radius) / py) - 1);
    const int r1 = std::min(width - 1, int((cy + radius) / py) + 1);
    for (int r = r0; r <= r1; ++r)
      for (int c = c0; c <= c1; ++c) {
        const double d = std::hypot((c + 0.5) * px - cx, (r + 0.5) * py - cy);
        double& p = crown[size_t(r) * size_t(width) + size_t(c)];
        p = std::max(p, std::clamp((radius - d) / std::min(px, py) + 0.5, 0.0, 1.0));
      }
  }
  for (int r = 0; r < width; ++r)
    for (int c = 0; c < width; ++c) {
      const size_t k = size_t(r) * size_t(width) + size_t(c);
      image[k] = float(180 - 120 * crown[k] + 20 * (unit() - 0.5));
      const double x = (c + 0.5) * px - extent_x / 2, y = (r + 0.5) * py - extent_y / 2;
      if (s.masked && std::hypot(x, y) > 0.45 * extent_x) image[k] = NAN;
    }
  return image;
}

TEST(SpacingEstimate, WithinTenPercentOfTheCrownsSpacing) {
  const int width = 256;
  const double pixel_m = 0.5;
  for (const Scene& s : {Scene{5, 0, 0, false}, Scene{8, 17, 0, false}, Scene{12.5, 33, 0.1, false},
                         Scene{20, 5, 0.15, false}, Scene{9, 61, 0.1, true}}) {
    const double estimate =
        estimate_spacing(orthophoto(s, width, pixel_m, pixel_m), width, width, pixel_m);
    EXPECT_NEAR(estimate / s.spacing_m, 1, 0.1)
        << "spacing " << s.spacing_m << " m, turned " << s.angle_deg << " deg, jitter " << s.jitter
        << ": " << estimate << " m";
    std::printf("spacing %5.1f m turned %2.0f deg jitter %.2f%s: estimated %6.2f m (%+.1f %%)\n",
                s.spacing_m, s.angle_deg, s.jitter, s.masked ? " masked" : "", estimate,
                100 * (estimate / s.spacing_m - 1));
  }
}

TEST(SpacingEstimate, TilesSummedAsOne) {
  const int width = 256, half = width / 2;
  const double pixel_m = 0.5, spacing_m = 7;
  const std::vector<float> image = orthophoto({spacing_m, 23, 0.1, false}, width, pixel_m, pixel_m);
  RingPower sum;
  for (int ty = 0; ty < 2; ++ty)
    for (int tx = 0; tx < 2; ++tx) {
      std::vector<float> tile;
      for (int r = 0; r < half; ++r)
        for (int c = 0; c < half; ++c)
          tile.push_back(image[size_t(ty * half + r) * size_t(width) + size_t(tx * half + c)]);
      const RingPower rings = ring_power(tile, half, half);
      if (sum.side == 0)
        sum = rings;
      else
        add_rings(sum, rings);
    }
  EXPECT_NEAR(spacing_from_rings(sum, pixel_m) / spacing_m, 1, 0.1);
}

// Pixels 0.8 times as wide as high (rHEALPix at 37 degrees): measured in metres through the
// pixel's axes, not in pixels.
TEST(SpacingEstimate, PixelsNotSquareOnTheGround) {
  const int width = 256;
  const double px = 0.4, py = 0.625, spacing_m = 8;  // both of area 0.25 m^2
  const std::vector<float> image = orthophoto({spacing_m, 0, 0.05, false}, width, px, py);
  const PixelAxes axes{px, 0, 0, -py};
  const double estimate =
      spacing_from_rings(ring_power(image, width, width, axes), axes.area_side());
  EXPECT_NEAR(estimate / spacing_m, 1, 0.1) << estimate;
  std::printf("pixels of %.3f x %.3f m: %.2f m through their axes, %.2f m as squares\n", px, py,
              estimate, estimate_spacing(image, width, width, 0.5));
}

// Brightness falling across the image (a slope's shading, haze) by far more than the crowns'
// contrast: the crowns' peak still found; the gradient alone, with no crowns, refused.
TEST(SpacingEstimate, ABrightnessGradientNeitherHidesNorFakesCrowns) {
  const int width = 256;
  const double pixel_m = 0.5, spacing_m = 9;
  std::vector<float> image = orthophoto({spacing_m, 12, 0.1, false}, width, pixel_m, pixel_m);
  std::vector<float> gradient(image.size());
  for (int r = 0; r < width; ++r)
    for (int c = 0; c < width; ++c) {
      const size_t k = size_t(r) * size_t(width) + size_t(c);
      gradient[k] = float(2.0 * c + 1.0 * r);
      image[k] += gradient[k];
    }
  const double estimate = estimate_spacing(image, width, width, pixel_m);
  EXPECT_NEAR(estimate / spacing_m, 1, 0.1) << estimate;
  EXPECT_THROW(estimate_spacing(gradient, width, width, pixel_m), std::runtime_error);
}

TEST(SpacingEstimate, ImagesTooSmallAreRefused) {
  std::vector<float> checkerboard(8 * 8);
  for (size_t k = 0; k < checkerboard.size(); ++k) checkerboard[k] = float((k + k / 8) % 2);
  try {
    estimate_spacing(checkerboard, 8, 8, 1);
    ADD_FAILURE() << "an 8 x 8 image was measured";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("too small"), std::string::npos) << e.what();
  }
}

TEST(SpacingEstimate, AUniformImageIsRefused) {
  EXPECT_THROW(estimate_spacing(std::vector<float>(64 * 64, 100.0f), 64, 64, 1),
               std::runtime_error);
}

}  // namespace
}  // namespace maquette::structures
