// The exemplar's measured over-use (exemplar_usage.h) on a two-class exemplar whose left class
// is one flat colour (every patch alike) and whose right class is noise, with an excluded square:
// every level has a usage, never negative, some pixel above its share; the flat class is
// over-used more than the noise; a coarser level's is the mean of its 2 x 2 children; a measure
// repeated gives the same values. And the count itself (usage_of_copy) on a hand-built copy
// whose counts are known.
#include "../exemplar_usage.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>

#include "core/splitmix64.h"
#include "painted_exemplar.h"

namespace maquette::synthesis {
namespace {

ExemplarPyramid pyramid() {
  const Exemplar exemplar =
      test::painted_exemplar(96, 64, false, [](Exemplar& e, int x, int y, size_t i) {
        const bool right = x >= e.width / 2;
        e.labels[i] = right ? 1 : 0;
        e.excluded[i] = x >= 10 && x < 20 && y >= 10 && y < 20;
        for (size_t k = 0; k < 3; ++k)
          e.rgb[3 * i + k] = right ? float(splitmix64_mix(3 * i + k) % 256) : 120.0f;
      });
  ExemplarPyramid p = analyse_exemplar(exemplar, kLevels, 2);
  measure_usage(p, {});
  return p;
}

TEST(ExemplarUsage, EveryLevelHasAUsageNeverNegative) {
  const ExemplarPyramid p = pyramid();
  for (const ExemplarLevel& level : p.levels) {
    ASSERT_EQ(level.usage.size(), size_t(level.width) * size_t(level.height));
    EXPECT_GE(*std::min_element(level.usage.begin(), level.usage.end()), 0.0f);
  }
  // The synthesis is not a permutation of the exemplar: some pixel is used above its share.
  EXPECT_GT(*std::max_element(p.levels[0].usage.begin(), p.levels[0].usage.end()), 0.0f);
}

// Per class of the fixture (0: flat, 1: noise), the mean and the largest usage of its allowed
// pixels at the finest level.
std::array<std::array<double, 2>, 2> class_usage(const ExemplarLevel& level) {
  std::array<std::array<double, 2>, 2> out{};
  std::array<int, 2> n{};
  for (const int32_t i : level.allowed) {
    const size_t c = level.labels[size_t(i)];
    out[c][0] += level.usage[size_t(i)];
    out[c][1] = std::max(out[c][1], double(level.usage[size_t(i)]));
    ++n[c];
  }
  for (size_t c = 0; c < 2; ++c) out[c][0] /= n[c];
  return out;
}

// In the flat class every patch is alike: the colour term does not tell its candidates apart and
// every pixel's k similar ones are the same few (ties go to the lower index), so its copy piles
// on a few pixels (its largest usage over 4 times the noise class's, its mean above it); the
// noise class's similar candidates differ from pixel to pixel.
TEST(ExemplarUsage, TheFlatClassIsOverUsedMoreThanTheNoise) {
  const auto u = class_usage(pyramid().levels[0]);
  EXPECT_GT(u[0][1], 4 * u[1][1]);
  EXPECT_GT(u[0][0], u[1][0]);
}

// A 4 x 3 level with (3, 2) excluded, and a copy of it: copy pixels (0, 0) and (1, 0) copy
// level pixel (2, 1), the excluded copy pixel (3, 2) copies (2, 1) too (not counted), the other
// 9 copy (0, 0). Counts: (0, 0) 9, (2, 1) 2, others 0. Each usage worked out by hand as the mean
// count over the allowed pixels of the 3 x 3 neighbourhood within the level, minus 1, at least 0.
TEST(ExemplarUsage, CountsTheAllowedCopiesOfEachPixel) {
  ExemplarLevel level;
  level.width = 4;
  level.height = 3;
  level.excluded.assign(12, 0);
  level.excluded[size_t(level.index(3, 2))] = 1;
  std::vector<int32_t> source(12, level.index(0, 0));
  source[size_t(level.index(0, 0))] = source[size_t(level.index(1, 0))] =
      source[size_t(level.index(3, 2))] = level.index(2, 1);
  const std::vector<float> expected = {9.0f / 4 - 1,
                                       11.0f / 6 - 1,
                                       0,
                                       0,  // row 0: (2, 0) 2 / 6, (3, 0) 2 / 4: below 1
                                       9.0f / 6 - 1,
                                       11.0f / 9 - 1,
                                       0,
                                       0,  // row 1: (2, 1) 2 / 8, (3, 1) 2 / 5
                                       0,
                                       0,
                                       0,
                                       0};  // row 2: 0 / 4, 2 / 6, 2 / 5, 2 / 3 (the excluded)
  const std::vector<float> usage = usage_of_copy(level, source);
  ASSERT_EQ(usage.size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(usage[i], expected[i], 1e-6) << i;
}

// A 7 x 1 level: label 0 black, black, white, white; label 1 grey, white and an excluded white
// pixel. The copy: label 0's pixels copy black, black, black, white (shares 3 / 4 and 1 / 4
// against the level's 2 / 4 each); label 1's grey and white pixels both copy the white one
// (white 2 / 2, grey 0 / 2, against 1 / 2 each); the excluded pixel copies black (not counted).
// Each ratio worked out by hand with the floor; grey's, below 1 / kExcessClamp, is clamped.
TEST(ExemplarUsage, TheColourExcessIsTheCopysShareOfEachColourOverTheExemplarsPerLabel) {
  ExemplarLevel level;
  level.width = 7;
  level.height = 1;
  const float greys[7] = {0, 0, 1, 1, 0.5f, 1, 1};
  for (const float g : greys) level.rgb.insert(level.rgb.end(), {g, g, g});
  level.labels = {0, 0, 0, 0, 1, 1, 1};
  level.excluded = {0, 0, 0, 0, 0, 0, 1};
  const std::vector<int32_t> source = {0, 1, 0, 2, 5, 5, 0};
  const double f = kExcessFloor;
  const double black0 = (0.75 + f) / (0.5 + f), white0 = (0.25 + f) / (0.5 + f),
               white1 = (1 + f) / (0.5 + f);
  const std::vector<double> expected = {black0,           black0, white0, white0,
                                        1 / kExcessClamp, white1, 1};
  const std::vector<float> excess = colour_excess_of_copy(level, source);
  ASSERT_EQ(excess.size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(excess[i], expected[i], 1e-6) << i;
}

TEST(ExemplarUsage, ACoarserLevelTakesTheMeanOfItsChildren) {
  const ExemplarPyramid p = pyramid();
  for (size_t l = 1; l < p.levels.size(); ++l) {
    const ExemplarLevel &fine = p.levels[l - 1], &coarse = p.levels[l];
    for (int y = 0; y < coarse.height; ++y)
      for (int x = 0; x < coarse.width; ++x) {
        const auto u = [&](int fx, int fy) {
          return double(fine.usage[size_t(
              fine.index(std::min(fx, fine.width - 1), std::min(fy, fine.height - 1)))]);
        };
        const double mean = (u(2 * x, 2 * y) + u(2 * x + 1, 2 * y) + u(2 * x, 2 * y + 1) +
                             u(2 * x + 1, 2 * y + 1)) /
                            4;
        EXPECT_NEAR(coarse.usage[size_t(coarse.index(x, y))], mean, 1e-6)
            << l << " " << x << " " << y;
      }
  }
}

// The copy is synthesized in tiles in parallel: on an exemplar of several tiles (the last ones
// partial), the same usage and colour excess as from the copy synthesized as one window.
TEST(ExemplarUsage, TheTiledCopyEqualsTheWholeWindowsCopy) {
  const Exemplar exemplar =
      test::painted_exemplar(352, 200, false, [](Exemplar& e, int x, int y, size_t i) {
        e.labels[i] = uint8_t((x / 50 + y / 40) % 3);
        e.excluded[i] = x >= 100 && x < 120 && y >= 30 && y < 60;
        for (size_t k = 0; k < 3; ++k)
          e.rgb[3 * i + k] = float((splitmix64_mix(3 * i + k) % 64) + 60 * e.labels[i]);
      });
  ExemplarPyramid p = analyse_exemplar(exemplar, kLevels, 2);
  measure_usage(p, {});
  const ExemplarLevel& finest = p.levels[0];
  SynthesisParams params;
  params.w_usage = 0;
  const std::vector<int32_t> whole =
      synthesize(p, own_label_guides(finest), params, {0, 0, finest.width, finest.height});
  EXPECT_EQ(finest.usage, usage_of_copy(finest, whole));
  EXPECT_EQ(finest.colour_excess, colour_excess_of_copy(finest, whole));
}

TEST(ExemplarUsage, AMeasureRepeatedGivesTheSameValues) {
  EXPECT_EQ(pyramid().levels[0].usage, pyramid().levels[0].usage);
}

}  // namespace
}  // namespace maquette::synthesis
