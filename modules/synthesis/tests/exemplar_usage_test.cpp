// The exemplar's measured over-use (exemplar_usage.h) on a two-class exemplar whose left class
// is one flat colour (every patch alike) and whose right class is noise, with an excluded square:
// every level has a usage, never negative, some pixel above its share; a coarser level's is the
// mean of its 2 x 2 children; a measure repeated gives the same values.
#include "../exemplar_usage.h"

#include <gtest/gtest.h>

#include <algorithm>

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

TEST(ExemplarUsage, AMeasureRepeatedGivesTheSameValues) {
  EXPECT_EQ(pyramid().levels[0].usage, pyramid().levels[0].usage);
}

}  // namespace
}  // namespace maquette::synthesis
