// The k-d tree's k nearest neighbours, exact and approximate, against a brute-force scan of the
// same points.
#include "../nearest_patches.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <random>
#include <utility>

namespace maquette::synthesis {
namespace {

float squared_distance(const std::vector<float>& points, int dims, int32_t a, int32_t b) {
  float d = 0;
  for (int i = 0; i < dims; ++i) {
    const float x =
        points[size_t(a) * size_t(dims) + size_t(i)] - points[size_t(b) * size_t(dims) + size_t(i)];
    d += x * x;
  }
  return d;
}

// The accepted candidates of query q by (squared distance, index): the brute-force answer.
template <class Accept>
std::vector<std::pair<float, int32_t>> scan(const std::vector<float>& points, int dims, int32_t q,
                                            const Accept& accept) {
  std::vector<std::pair<float, int32_t>> out;
  const auto n = int32_t(points.size() / size_t(dims));
  for (int32_t c = 0; c < n; ++c)
    if (accept(q, c)) out.emplace_back(squared_distance(points, dims, q, c), c);
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<int32_t> iota(int32_t n) {
  std::vector<int32_t> out(size_t(n), 0);
  for (int32_t i = 0; i < n; ++i) out[size_t(i)] = i;
  return out;
}

// n coordinates drawn from the standard normal distribution (no ties: the approximation shows).
std::vector<float> normal_points(size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<float> normal(0.0f, 1.0f);
  std::vector<float> out(n);
  for (float& x : out) x = normal(rng);
  return out;
}

TEST(NearestPatches, EqualsBruteForceWithTiesAndAFilter) {
  constexpr int kDims = 3, kPoints = 2000, kK = 4;
  std::mt19937 rng(7);
  // Coordinates on a coarse lattice: many equal distances, so the tie rule is exercised.
  std::uniform_int_distribution<int> lattice(0, 6);
  std::vector<float> points(size_t(kPoints) * kDims);
  for (float& x : points) x = float(lattice(rng));
  const std::vector<int32_t> all = iota(kPoints);
  const auto accept = [](int32_t q, int32_t c) { return c != q && (c % 5) != 0; };

  const std::vector<int32_t> found = nearest_patches(points, kDims, all, all, kK, 0.0f, accept);
  for (int32_t q = 0; q < kPoints; ++q) {
    const auto exact = scan(points, kDims, q, accept);
    for (int j = 0; j < kK; ++j)
      ASSERT_EQ(found[size_t(q) * kK + size_t(j)], exact[size_t(j)].second) << "query " << q;
  }
}

// The (1 + eps) search (Arya et al.): each j-th found within (1 + eps)^2 of the j-th exact squared
// distance, sorted, distinct and accepted; and it must actually differ from the exact search
// somewhere (else the bound is not exercised) while skipping no query's k.
TEST(NearestPatches, ApproximateWithinItsBoundOfBruteForce) {
  constexpr int kDims = 8, kPoints = 3000, kK = 8;
  constexpr float kEps = 0.25f;
  const std::vector<float> points = normal_points(size_t(kPoints) * kDims, 11);
  const std::vector<int32_t> all = iota(kPoints);
  const auto accept = [](int32_t q, int32_t c) { return c != q && (c % 7) != 3; };

  const std::vector<int32_t> found = nearest_patches(points, kDims, all, all, kK, kEps, accept);
  int differing = 0;
  for (int32_t q = 0; q < kPoints; ++q) {
    const auto exact = scan(points, kDims, q, accept);
    std::vector<int32_t> seen;
    float previous = 0;
    for (int j = 0; j < kK; ++j) {
      const int32_t c = found[size_t(q) * kK + size_t(j)];
      ASSERT_GE(c, 0) << "query " << q << ", " << j << "-th";
      ASSERT_TRUE(accept(q, c)) << "query " << q << ", " << j << "-th: " << c;
      ASSERT_EQ(std::count(seen.begin(), seen.end(), c), 0) << "query " << q << ": " << c;
      seen.push_back(c);
      const float d = squared_distance(points, kDims, q, c);
      ASSERT_GE(d, previous) << "query " << q << ", " << j << "-th";
      previous = d;
      ASSERT_LE(d, exact[size_t(j)].first * (1 + kEps) * (1 + kEps))
          << "query " << q << ", " << j << "-th: " << c << " against " << exact[size_t(j)].second;
      differing += c != exact[size_t(j)].second;
    }
  }
  EXPECT_GT(differing, 0);
}

// The same queries give the same bits whatever the threads: one thread against the default.
TEST(NearestPatches, ApproximateIsTheSameOnOneThread) {
  constexpr int kDims = 8, kPoints = 3000, kK = 8;
  const std::vector<float> points = normal_points(size_t(kPoints) * kDims, 13);
  const std::vector<int32_t> all = iota(kPoints);
  const auto accept = [](int32_t q, int32_t c) { return c != q; };
  const auto parallel = nearest_patches(points, kDims, all, all, kK, 0.25f, accept);
  tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  EXPECT_EQ(nearest_patches(points, kDims, all, all, kK, 0.25f, accept), parallel);
}

TEST(NearestPatches, FewerAcceptedThanKLeavesMinusOne) {
  const std::vector<float> points = {0, 1, 2, 3};
  const std::vector<int32_t> all = {0, 1, 2, 3};
  const auto found =
      nearest_patches(points, 1, all, {0}, 3, 0.0f, [](int32_t, int32_t c) { return c >= 2; });
  EXPECT_EQ(found, (std::vector<int32_t>{2, 3, -1}));
}

}  // namespace
}  // namespace maquette::synthesis
