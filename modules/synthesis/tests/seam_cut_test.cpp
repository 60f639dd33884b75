// The minimum-error cut (seam_cut.h) against an exhaustive search over every path, on a known
// channel of no error, with no error at all (straight at the pins' depth), and over a stretch
// between two pins alone (the same cut whatever band holds it).
#include "../seam_cut.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <limits>
#include <vector>

#include "core/error.h"
#include "core/splitmix64.h"

namespace maquette::synthesis {
namespace {

// The cost seam_cut minimizes: per position the errors at t - 1 and t.
double path_cost(const std::vector<float>& error, int length, const std::vector<int>& cut) {
  double sum = 0;
  for (int i = 0; i < length; ++i)
    sum += error[size_t(cut[size_t(i)] - 1) * size_t(length) + size_t(i)] +
           error[size_t(cut[size_t(i)]) * size_t(length) + size_t(i)];
  return sum;
}

std::vector<float> random_errors(int length, int depth, uint64_t seed) {
  std::vector<float> error(size_t(length) * size_t(depth));
  for (size_t i = 0; i < error.size(); ++i) error[i] = float(splitmix64_mix(seed + i) % 1000);
  return error;
}

TEST(SeamCut, IsTheLeastCostPathBetweenThePinsOfAnExhaustiveSearch) {
  const int depth = 5, pin = 6;  // one stretch: positions 0 .. 5, pinned at 2 at 0 and 6
  for (uint64_t seed = 0; seed < 20; ++seed) {
    const auto error = random_errors(pin, depth, seed * 1000);
    double best = std::numeric_limits<double>::infinity();
    std::vector<int> path(pin, depth / 2);
    for (int code = 0; code < 243; ++code) {  // 3^5 steps from the pin
      bool ok = true;
      for (int i = 1, c = code; i < pin; ++i, c /= 3) {
        path[size_t(i)] = path[size_t(i - 1)] + c % 3 - 1;
        ok = ok && path[size_t(i)] >= 1 && path[size_t(i)] < depth;
      }
      if (ok && std::abs(path[size_t(pin - 1)] - depth / 2) <= 1)
        best = std::min(best, path_cost(error, pin, path));
    }
    const auto cut = seam_cut(error, 12, pin, depth, pin);
    EXPECT_EQ(cut[0], depth / 2);
    for (int i = 1; i < pin; ++i) EXPECT_LE(std::abs(cut[size_t(i)] - cut[size_t(i - 1)]), 1);
    EXPECT_EQ(path_cost(error, pin, cut), best) << "seed " << seed;
  }
}

TEST(SeamCut, FollowsAChannelOfNoErrorAndRunsStraightWithNoErrorAtAll) {
  const int length = 128, depth = 32, pin = 64;
  std::vector<float> error(size_t(length) * size_t(depth), 1.0f);
  for (int i = 0; i < length; ++i)
    error[size_t(4 * length + i)] = error[size_t(5 * length + i)] = 0;
  const auto cut = seam_cut(error, 0, length, depth, pin);
  // From the pin at 16 down one a step to 5, along it, and back up to meet the next pin.
  for (int i = 0; i < length; ++i) {
    const int k = i % pin;
    EXPECT_EQ(cut[size_t(i)], k <= 11 ? 16 - k : k >= 53 ? 5 + (k - 53) : 5) << i;
  }
  const auto straight = seam_cut(std::vector<float>(error.size(), 0.0f), 0, length, depth, pin);
  EXPECT_EQ(straight, std::vector<int>(size_t(length), depth / 2));
}

TEST(SeamCut, AStretchBetweenTwoPinsGetsTheSameCutInAnyBand) {
  const int depth = 32, pin = 64;
  const auto error = random_errors(4 * pin, depth, 7);
  const auto whole = seam_cut(error, 0, 4 * pin, depth, pin);
  // The band's third stretch alone, at its global position.
  std::vector<float> part(size_t(pin) * size_t(depth));
  for (int t = 0; t < depth; ++t)
    for (int i = 0; i < pin; ++i)
      part[size_t(t * pin + i)] = error[size_t(t * 4 * pin + 2 * pin + i)];
  const auto cut = seam_cut(part, 2 * pin, pin, depth, pin);
  EXPECT_EQ(cut, std::vector<int>(whole.begin() + 2 * pin, whole.begin() + 3 * pin));
  for (const int t : whole) {
    EXPECT_GE(t, 1);
    EXPECT_LT(t, depth);
  }
}

TEST(SeamCut, RefusesABandThatDoesNotStartAndEndAtPins) {
  const std::vector<float> error(64 * 32, 0.0f);
  EXPECT_THROW(seam_cut(error, 32, 64, 32, 64), Error);
  EXPECT_THROW(seam_cut(std::vector<float>(96 * 32), 0, 96, 32, 64), Error);
  EXPECT_THROW(seam_cut(std::vector<float>(64 * 2), 0, 64, 2, 64), Error);
  EXPECT_NO_THROW(seam_cut(error, 128, 64, 32, 64));
}

}  // namespace
}  // namespace maquette::synthesis
