#include "core/round_half_away.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace maquette {
namespace {

// The oracle is std::llround, on the values where rounding is delicate (halves, their neighbours
// one ulp away, integers, the ends of the range) and on random values of every magnitude.
TEST(RoundHalfAway, IsLlround) {
  std::vector<double> values = {0.0,
                                -0.0,
                                0.5,
                                -0.5,
                                1.5,
                                -1.5,
                                2.5,
                                -2.5,
                                1e15 + 0.5,
                                4503599627370495.5,
                                -4503599627370495.5,
                                9.2e18,
                                -9.2e18};
  for (int64_t k = -1000; k <= 1000; ++k) {
    const double half = double(k) + 0.5;
    for (const double v : {half, double(k)})
      values.insert(values.end(), {v, std::nextafter(v, -INFINITY), std::nextafter(v, INFINITY)});
  }
  // Halves and whole numbers, and their neighbours, at the powers of two where the spacing of
  // doubles doubles (up to 2^53, where every double is whole), and the largest double below 1/2.
  for (int e = 0; e <= 54; ++e)
    for (const double base : {std::exp2(e), std::exp2(e) - 0.5, std::exp2(e) + 0.5})
      for (const double sign : {1.0, -1.0}) {
        const double v = sign * base;
        values.insert(values.end(), {v, std::nextafter(v, -INFINITY), std::nextafter(v, INFINITY)});
      }
  values.insert(values.end(), {0.49999999999999994, -0.49999999999999994});
  std::mt19937_64 random(19);
  std::uniform_real_distribution<double> exponent(-20, 62), unit(-1, 1);
  for (int i = 0; i < 100000; ++i) values.push_back(unit(random) * std::exp2(exponent(random)));
  for (const double v : values) ASSERT_EQ(round_half_away(v), std::llround(v)) << v;
}

}  // namespace
}  // namespace maquette
