// select_quantile_range (render/quantile_select.h) against image/stretch.h's quantile_range, two
// nth_elements over all the values: the same quantiles for values with NaN, infinities, both
// zeros, negatives, many ties (texels interpolated from bytes) and few values.
#include "render/quantile_select.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "image/stretch.h"

namespace maquette {
namespace {

std::vector<float> values(size_t n, std::mt19937& random, bool spread) {
  std::uniform_int_distribution<int> byte(0, 255), kind(0, 99);
  std::uniform_real_distribution<float> fraction(0, 1), wide(-1e6f, 1e6f);
  std::vector<float> v;
  for (size_t i = 0; i < n; ++i) {
    const int k = kind(random);
    if (k == 0)
      v.push_back(NAN);
    else if (k == 1)
      v.push_back(INFINITY);
    else if (k == 2)
      v.push_back(-INFINITY);
    else if (k == 3)
      v.push_back(-0.0f);
    else if (k == 4)
      v.push_back(0.0f);
    else if (spread && k < 30)
      v.push_back(wide(random));
    else if (k < 60)
      v.push_back(float(byte(random)));  // ties
    else
      v.push_back(float(byte(random)) + fraction(random));
  }
  return v;
}

TEST(QuantileSelect, SameQuantilesAsTwoNthElements) {
  std::mt19937 random(19);
  for (const size_t n : {size_t(0), size_t(1), size_t(2), size_t(7), size_t(1000), size_t(300000)})
    for (const bool spread : {false, true})
      for (const auto& [q0, q1] :
           {std::pair{0.02, 0.98}, std::pair{0.0, 1.0}, std::pair{0.5, 0.5}}) {
        std::vector<float> v = values(n, random, spread);
        const StretchRange got = select_quantile_range(v, q0, q1);
        const StretchRange want = quantile_range(v, q0, q1);
        EXPECT_EQ(got.first, want.first) << n << " values, q " << q0;
        EXPECT_EQ(got.second, want.second) << n << " values, q " << q1;
      }
  // Only non-finite values: no quantile.
  const std::vector<float> none{NAN, INFINITY, -INFINITY};
  EXPECT_EQ(select_quantile_range(none, 0.02, 0.98), (StretchRange{0.0, 1.0}));
}

}  // namespace
}  // namespace maquette
