// The completion on synthetic images: a periodic texture filled back to its period (the exact
// answer), the pixels outside the hole and its band kept bit for bit, nodata kept, bad params
// refused. The finest level's mode vote on hand-built votes.
#include "../inpaint.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <utility>

#include "../inpaint_mode.h"
#include "../patchmatch.h"
#include "core/error.h"
#include "synthetic_images.h"

namespace maquette::synthesis {
namespace {

constexpr int kPeriodX = 9, kPeriodY = 7;

// A 9 x 7 period of random colours.
PatchImage periodic(int w, int h) { return test::periodic_texture(w, h, kPeriodX, kPeriodY, 11); }

// The mode of one-channel votes (weights `weights`) by mean_shift_mode from their weighted mean.
double mode_of(const std::vector<float>& votes, const std::vector<double>& weights) {
  std::vector<const float*> values;
  double mode = 0, total = 0, next = 0;
  for (size_t j = 0; j < votes.size(); ++j) {
    values.push_back(&votes[j]);
    mode += weights[j] * votes[j];
    total += weights[j];
  }
  mode /= total;
  mean_shift_mode(values.data(), weights.data(), votes.size(), 1, &mode, &next);
  return mode;
}

// Votes 0, 0, 0.1, 1, 1 of equal weight: their mean, 0.42, is a value none of them proposes; the
// mode is the peak of their Gaussian kernel density (variance kModeBandwidth x the votes'
// variance, 0.2256), found here independently on a grid of 1e-4: 0.0328, by the three votes
// near 0.
TEST(InpaintMode, TakesThePeakOfTheVotesNotTheirMean) {
  const std::vector<float> votes = {0, 0, 0.1f, 1, 1};
  const double kernel = kModeBandwidth * 0.2256;
  const auto density = [&](double at) {
    double sum = 0;
    for (const float v : votes) sum += std::exp(-(v - at) * (v - at) / (2 * kernel));
    return sum;
  };
  double peak = -1;
  for (int i = -5000; i <= 15000; ++i) {
    if (peak < -0.5 || density(i * 1e-4) > density(peak)) peak = i * 1e-4;
  }
  EXPECT_NEAR(peak, 0.0328, 1e-4);
  const double mode = mode_of(votes, std::vector<double>(votes.size(), 1.0));
  std::cout << "mode " << mode << ", the grid's peak " << peak << "\n";
  // The steps stop once one moves less than 1e-2 kernel widths: within 0.003 of the peak.
  EXPECT_NEAR(mode, peak, 0.003);
  // A vote of weight 2 counts as two votes (the completeness votes' mean enters a pixel's
  // vote once, with their total weight).
  EXPECT_DOUBLE_EQ(mode_of({0, 0.1f, 1, 1}, {2, 1, 1, 1}), mode);
  // The weights decide: the two votes at 1 weighing 4 each take the mode there.
  EXPECT_NEAR(mode_of(votes, {1, 1, 1, 4, 4}), 1.0, 0.05);
}

TEST(InpaintMode, OneVoteOrVotesThatAgreeGiveThemselves) {
  EXPECT_EQ(mode_of({0.7f}, {0.3}), double(0.7f));
  EXPECT_EQ(mode_of({0.7f, 0.7f, 0.7f}, {1, 2, 3}), double(0.7f));
  // Several channels: the distance over all of them, the mode the vector two votes of three share.
  const float a[] = {0, 1}, b[] = {0, 1}, c[] = {1, 0};
  const float* values[] = {a, b, c};
  const double weights[] = {1, 1, 1};
  double mode[] = {1.0 / 3, 2.0 / 3}, next[2];
  mean_shift_mode(values, weights, 3, 2, mode, next);
  EXPECT_NEAR(mode[0], 0, 0.01);
  EXPECT_NEAR(mode[1], 1, 0.01);
}

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
            "nodata: nothing is left to fill it from (the hole covers 81 % of the image with its "
            "context; give a smaller hole or a larger region)");
}

}  // namespace
}  // namespace maquette::synthesis
