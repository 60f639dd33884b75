// The completion on synthetic images: a periodic texture filled back to its period (the exact
// answer), the pixels outside the hole and its band kept bit for bit, nodata kept, bad params
// refused.
#include "../inpaint.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <utility>

#include "../patchmatch.h"
#include "core/error.h"
#include "synthetic_images.h"

namespace maquette::synthesis {
namespace {

constexpr int kPeriodX = 9, kPeriodY = 7;

// A 9 x 7 period of random colours.
PatchImage periodic(int w, int h) { return test::periodic_texture(w, h, kPeriodX, kPeriodY, 11); }

TEST(Inpaint, FillsAPeriodicTextureBackToItsPeriod) {
  const PatchImage truth = periodic(128, 112);
  const auto hole = test::square_mask(128, 112, 44, 38, 36);
  PatchImage damaged = truth;
  for (size_t i = 0; i < hole.size(); ++i) {
    if (hole[i] != 0) std::fill_n(damaged.values.begin() + i * 3, 3, 0.0f);
  }
  // The mean largest channel error over the hole and the share of its pixels within 0.5.
  const auto errors = [&](const InpaintParams& params) {
    const PatchImage filled = inpaint(damaged, hole, params, PatchMatch());
    double error = 0;
    size_t exact = 0, count = 0;
    for (size_t i = 0; i < hole.size(); ++i) {
      if (hole[i] == 0) continue;
      double worst = 0;
      for (int c = 0; c < 3; ++c) {
        worst =
            std::max(worst, double(std::abs(filled.values[i * 3 + c] - truth.values[i * 3 + c])));
      }
      error += worst;
      exact += worst < 0.5;
      ++count;
    }
    return std::pair{error / double(count), double(exact) / double(count)};
  };
  // Coherence alone (Wexler): the period everywhere (measured: every pixel exact).
  InpaintParams coherence_alone;
  coherence_alone.completeness = 0;
  const auto [error, exact] = errors(coherence_alone);
  std::cout << "coherence alone: " << error << ", " << exact << "\n";
  EXPECT_LE(error, 0.01);
  EXPECT_GE(exact, 0.999);
  // The defaults' completeness votes (weight 3) pull the ring's patches in at every phase before
  // the field converges: measured 0.50 and 0.86.
  const auto [default_error, default_exact] = errors(InpaintParams{});
  std::cout << "defaults: " << default_error << ", " << default_exact << "\n";
  EXPECT_LE(default_error, 1.0);
  EXPECT_GE(default_exact, 0.85);
}

TEST(Inpaint, KeepsEveryPixelBeyondTheBandAndTheNodata) {
  PatchImage image = periodic(96, 80);
  // A smooth ramp over the period, so that the band's resynthesis changes it measurably.
  for (int y = 0; y < 80; ++y) {
    for (int x = 0; x < 96; ++x) image.pixel(x, y)[1] += float(x);
  }
  for (int y = 0; y < 5; ++y) std::fill_n(image.pixel(0, y), 3 * 20, NAN);  // nodata corner
  const auto hole = test::square_mask(96, 80, 30, 30, 16);
  InpaintParams params;
  params.band = 4;
  const PatchImage filled = inpaint(image, hole, params, PatchMatch());
  size_t changed_beyond = 0, nan_kept = 0, finite_in_hole = 0;
  for (int y = 0; y < 80; ++y) {
    for (int x = 0; x < 96; ++x) {
      const size_t i = size_t(y) * 96 + x;
      const bool in_band = x >= 26 && x < 50 && y >= 26 && y < 50;
      for (int c = 0; c < 3; ++c) {
        const float a = image.values[i * 3 + c], b = filled.values[i * 3 + c];
        if (std::isnan(a)) {
          nan_kept += std::isnan(b);
        } else if (!in_band && a != b) {
          ++changed_beyond;
        }
        if (hole[i] != 0) finite_in_hole += std::isfinite(b);
      }
    }
  }
  EXPECT_EQ(changed_beyond, 0u);
  EXPECT_EQ(nan_kept, 5u * 20 * 3);
  EXPECT_EQ(finite_in_hole, 16u * 16 * 3);
}

// A pixel with one channel NaN (an RGB raster's band at its nodata value) is nodata as a whole:
// matching it would give NaN costs that no search replaces, and NaN votes over the whole fill.
TEST(Inpaint, APixelWithOneNanChannelIsNodataNotAReference) {
  PatchImage image = periodic(96, 80);
  for (int y = 20; y < 24; ++y) {
    for (int x = 60; x < 64; ++x) image.pixel(x, y)[1] = NAN;
  }
  const auto hole = test::square_mask(96, 80, 30, 30, 16);
  const PatchImage filled = inpaint(image, hole, InpaintParams{}, PatchMatch());
  size_t finite_in_hole = 0, kept = 0;
  for (size_t i = 0; i < hole.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      const float a = image.values[i * 3 + c], b = filled.values[i * 3 + c];
      if (hole[i] != 0) finite_in_hole += std::isfinite(b);
      if (std::isnan(a)) kept += std::isnan(b);
    }
  }
  EXPECT_EQ(finite_in_hole, 16u * 16 * 3);
  EXPECT_EQ(kept, 16u);
}

TEST(Inpaint, AnEmptyHoleLeavesTheImageAsItIs) {
  const PatchImage image = periodic(40, 40);
  const PatchImage filled =
      inpaint(image, std::vector<uint8_t>(40 * 40, 0), InpaintParams{}, PatchMatch());
  EXPECT_EQ(filled.values, image.values);
}

TEST(Inpaint, RefusesBadParamsAndAnImageWithoutAPatchOutsideTheHole) {
  const PatchImage image = periodic(40, 40);
  const auto hole = test::square_mask(40, 40, 10, 10, 8);
  const auto message = [&](InpaintParams p, const std::vector<uint8_t>& mask) {
    try {
      inpaint(image, mask, p, PatchMatch());
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  InpaintParams even;
  even.patch = 6;
  EXPECT_EQ(message(even, hole), "inpaint: patch 6 is not an odd side of at least 3");
  EXPECT_EQ(message({}, std::vector<uint8_t>(10, 0)),
            "inpaint: the hole mask has 10 pixels, the image 1600");
  EXPECT_EQ(message({}, test::square_mask(40, 40, 2, 2, 36)),
            "inpaint: no 7 x 7 patch lies wholly outside the hole, its band (3 pixels) and the "
            "nodata");
}

}  // namespace
}  // namespace maquette::synthesis
