// The clone brush's copy on synthetic images: a periodic texture cloned by a whole number of
// periods onto a blanked destination is the image again (the band included); a checkerboard cloned
// at twice the size has squares twice as large; the foreshortening map against its cosine; bad
// input refused.
#include "../clone.h"

#include <gtest/gtest.h>

#include <cmath>

#include "../patchmatch.h"
#include "core/error.h"
#include "synthetic_images.h"

namespace maquette::synthesis {
namespace {

TEST(Clone, APeriodicTextureClonedByWholePeriodsOntoABlankIsWholeAgain) {
  constexpr int kW = 120, kH = 100, kPx = 9, kPy = 7;
  const PatchImage image = test::periodic_texture(kW, kH, kPx, kPy, 5);
  CloneParams params;
  params.offset_x = 4 * kPx;
  params.offset_y = 5 * kPy;
  params.fill.completeness = 0;  // coherence alone: exact on a periodic texture
  // The destination (24 x 24 at (46, 43)) blanked first: only the copy can bring it back.
  PatchImage blanked = image;
  const auto destination = test::square_mask(kW, kH, 10 + 4 * kPx, 8 + 5 * kPy, 24);
  for (size_t i = 0; i < destination.size(); ++i) {
    if (destination[i] != 0) std::fill_n(blanked.values.begin() + i * 3, 3, 0.0f);
  }
  const PatchImage out = clone(blanked, test::square_mask(kW, kH, 10, 8, 24), params, PatchMatch());
  float worst = 0;
  for (size_t i = 0; i < image.values.size(); ++i) {
    worst = std::max(worst, std::abs(out.values[i] - image.values[i]));
  }
  EXPECT_LT(worst, 0.5f);
}

// Without a band (fill.band 0) nothing is resynthesized: the copy, and every other pixel as it was.
TEST(Clone, WithoutABandItIsAPlainCopy) {
  constexpr int kW = 60, kH = 50;
  const PatchImage image = test::periodic_texture(kW, kH, 9, 7, 5);
  CloneParams params;
  params.offset_x = 20;
  params.offset_y = 15;
  params.fill.band = 0;
  const PatchImage out = clone(image, test::square_mask(kW, kH, 5, 5, 12), params, PatchMatch());
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      const bool copied = x >= 25 && x < 37 && y >= 20 && y < 32;
      const float* expected = copied ? image.pixel(x - 20, y - 15) : image.pixel(x, y);
      for (int c = 0; c < 3; ++c) ASSERT_EQ(out.pixel(x, y)[c], expected[c]) << x << ", " << y;
    }
  }
}

TEST(Clone, ACheckerboardClonedAtTwiceTheSizeHasSquaresTwiceAsLarge) {
  constexpr int kW = 160, kH = 120, kSquare = 6;
  PatchImage image(kW, kH, 3);
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      std::fill_n(image.pixel(x, y), 3, ((x / kSquare + y / kSquare) % 2) != 0 ? 200.0f : 40.0f);
    }
  }
  CloneParams params;
  params.offset_x = 70;
  params.offset_y = 20;
  params.linear = {2, 0, 0, 2};
  // Source 24 x 24 at (12, 12): its centre (23.5, 23.5) lands at (93.5, 43.5), 48 x 48 around it.
  const PatchImage out = clone(image, test::square_mask(kW, kH, 12, 12, 24), params, PatchMatch());
  // Along the destination's middle row, away from the band: the runs of one colour.
  const int row = 43, band = params.fill.band;
  std::vector<int> runs;
  int run = 0;
  float previous = -1;
  for (int x = 70 + band; x < 118 - band; ++x) {
    const float v = out.pixel(x, row)[0] > 120 ? 1.0f : 0.0f;
    if (v == previous || previous < 0) {
      ++run;
    } else {
      runs.push_back(run);
      run = 1;
    }
    previous = v;
  }
  // The inner runs (the first and last are cut by the band) are whole squares, 2 x 6 wide.
  ASSERT_GE(runs.size(), 3u);
  for (size_t i = 1; i < runs.size(); ++i) EXPECT_EQ(runs[i], 2 * kSquare) << "run " << i;
}

TEST(Clone, ForeshorteningScalesAlongTheSlopeByTheCosineRatio) {
  const auto m = foreshortening(0, 30, 90);  // onto a 30 degree slope falling towards +y
  EXPECT_NEAR(m[0], 1, 1e-12);
  EXPECT_NEAR(m[3], std::cos(M_PI / 6), 1e-12);
  EXPECT_NEAR(m[1], 0, 1e-12);
  const auto back = foreshortening(30, 0, 45);  // off a slope: longer along the diagonal
  const double k = 1 / std::cos(M_PI / 6);
  // The diagonal (1, 1) / sqrt(2) scaled by k, the other diagonal kept.
  EXPECT_NEAR((back[0] + back[1] + back[2] + back[3]) / 2, k, 1e-12);
  EXPECT_NEAR((back[0] - back[1] - back[2] + back[3]) / 2, 1, 1e-12);
}

TEST(Clone, RefusesAnEmptySourceAndASingularMap) {
  const PatchImage image(40, 40, 3);
  const auto message = [&](const std::vector<uint8_t>& mask, std::array<double, 4> linear) {
    CloneParams p;
    p.linear = linear;
    try {
      clone(image, mask, p, PatchMatch());
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message(std::vector<uint8_t>(1600, 0), {1, 0, 0, 1}),
            "clone: the source region is empty");
  EXPECT_EQ(message(test::square_mask(40, 40, 5, 5, 8), {1, 2, 2, 4}),
            "clone: the map is singular");
}

}  // namespace
}  // namespace maquette::synthesis
