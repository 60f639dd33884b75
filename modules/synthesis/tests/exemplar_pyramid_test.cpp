// The PCA basis of several paintings side by side (exemplar_pyramid.h, combined_exemplar.h) is
// fitted over the paintings' pixels alone: refilling the gap between them (beyond what the blur
// and the neighbourhoods of the paintings' pixels read) leaves every level's basis bit for bit,
// and the finest level's mean is the mean of each painting's own 3 x 3 neighbourhoods (borders
// clamped), computed here.
#include "../exemplar_pyramid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

#include "../combined_exemplar.h"
#include "../synthesis.h"
#include "core/splitmix64.h"
#include "painted_exemplar.h"

namespace maquette::synthesis {
namespace {

// A painting of noise with an excluded square; `seed` tells two paintings apart.
Exemplar painting(int width, int height, uint64_t seed) {
  return test::painted_exemplar(width, height, false, [seed](Exemplar& e, int x, int y, size_t i) {
    e.labels[i] = x < e.width / 2 ? 0 : 1;
    e.excluded[i] = x >= 4 && x < 10 && y >= 4 && y < 10;
    for (size_t c = 0; c < 3; ++c)
      e.rgb[3 * i + c] = float(splitmix64_mix(seed * 1000003 + 3 * i + c) % 256);
  });
}

// A painting 40 x 24 (columns 0..39) and one 36 x 32 from column 104 (the first multiple of 8
// at least 64 past 40).
std::vector<Exemplar> paintings() { return {painting(40, 24, 1), painting(36, 32, 2)}; }

TEST(ExemplarPyramid, TheBasisOfSeveralPaintingsIgnoresTheGapsFiller) {
  std::vector<Placement> at;
  const Exemplar combined = combine_exemplars(paintings(), at);
  ASSERT_EQ(at.size(), 2u);
  ASSERT_EQ(at[1].x0, 104);
  // At the coarsest level (3) a painting's neighbourhoods read one pixel past its edge, which
  // blurs finest columns up to 54 (the first painting's side) and from 82 (the second's): the
  // columns between are refilled with other colours.
  Exemplar refilled = combined;
  for (int y = 0; y < refilled.height; ++y)
    for (int x = 56; x < 81; ++x)
      for (size_t c = 0; c < 3; ++c)
        refilled.rgb[3 * (size_t(y) * size_t(refilled.width) + size_t(x)) + c] =
            float((x * 37 + y * 11 + int(c) * 101) % 256);
  const ExemplarPyramid a = analyse_exemplar(combined, kLevels, 2, at);
  const ExemplarPyramid b = analyse_exemplar(refilled, kLevels, 2, at);
  for (size_t l = 0; l < size_t(kLevels); ++l) {
    EXPECT_EQ(a.levels[l].basis.mean, b.levels[l].basis.mean) << "level " << l;
    EXPECT_EQ(a.levels[l].basis.axes, b.levels[l].basis.axes) << "level " << l;
  }
}

TEST(ExemplarPyramid, TheFinestMeanIsThePaintingsOwnNeighbourhoodsMean) {
  std::vector<Placement> at;
  const std::vector<Exemplar> parts = paintings();
  const ExemplarPyramid p = analyse_exemplar(combine_exemplars(parts, at), kLevels, 2, at);
  std::array<double, kPatchValues> mean{};
  double n = 0;
  for (const Exemplar& e : parts)
    for (int y = 0; y < e.height; ++y)
      for (int x = 0; x < e.width; ++x, ++n) {
        size_t o = 0;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const size_t i = size_t(std::clamp(y + dy, 0, e.height - 1)) * size_t(e.width) +
                             size_t(std::clamp(x + dx, 0, e.width - 1));
            for (size_t c = 0; c < 3; ++c) mean[o++] += e.rgb[3 * i + c] / 255.0;
          }
      }
  for (size_t v = 0; v < size_t(kPatchValues); ++v)
    EXPECT_NEAR(p.levels[0].basis.mean[v], mean[v] / n, 1e-6) << "value " << v;
}

}  // namespace
}  // namespace maquette::synthesis
