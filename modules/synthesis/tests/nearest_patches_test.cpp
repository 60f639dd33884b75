// The k-d tree's k nearest neighbours against a brute-force scan of the same points.
#include "../nearest_patches.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <utility>

namespace maquette::synthesis {
namespace {

TEST(NearestPatches, EqualsBruteForceWithTiesAndAFilter) {
  constexpr int kDims = 3, kPoints = 2000, kK = 4;
  std::mt19937 rng(7);
  // Coordinates on a coarse lattice: many equal distances, so the tie rule is exercised.
  std::uniform_int_distribution<int> lattice(0, 6);
  std::vector<float> points(size_t(kPoints) * kDims);
  for (float& x : points) x = float(lattice(rng));
  std::vector<int32_t> all(kPoints);
  for (int32_t i = 0; i < kPoints; ++i) all[size_t(i)] = i;
  const auto accept = [](int32_t q, int32_t c) { return c != q && (c % 5) != 0; };

  const std::vector<int32_t> found = nearest_patches(points, kDims, all, all, kK, accept);
  for (int32_t q = 0; q < kPoints; ++q) {
    std::vector<std::pair<float, int32_t>> scan;
    for (int32_t c = 0; c < kPoints; ++c) {
      if (!accept(q, c)) continue;
      float d = 0;
      for (int i = 0; i < kDims; ++i) {
        const float x =
            points[size_t(q) * kDims + size_t(i)] - points[size_t(c) * kDims + size_t(i)];
        d += x * x;
      }
      scan.emplace_back(d, c);
    }
    std::sort(scan.begin(), scan.end());
    for (int j = 0; j < kK; ++j)
      ASSERT_EQ(found[size_t(q) * kK + size_t(j)], scan[size_t(j)].second) << "query " << q;
  }
}

TEST(NearestPatches, FewerAcceptedThanKLeavesMinusOne) {
  const std::vector<float> points = {0, 1, 2, 3};
  const std::vector<int32_t> all = {0, 1, 2, 3};
  const auto found =
      nearest_patches(points, 1, all, {0}, 3, [](int32_t, int32_t c) { return c >= 2; });
  EXPECT_EQ(found, (std::vector<int32_t>{2, 3, -1}));
}

}  // namespace
}  // namespace maquette::synthesis
