// The gradient noise kernel (gradient_noise.h): its two paths give the same bits, and the noise
// is gradient noise with Perlin's 12 edge gradients, seeded, with a period of 2^32 nodes.
#include "../gradient_noise.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <map>
#include <vector>

namespace maquette::texture {
namespace {

Points points(const std::vector<Vec3d>& p) {
  Points out;
  for (const Vec3d& x : p) out.push_back(x);
  return out;
}

std::vector<float> noise(const std::vector<Vec3d>& p, double scale, const Vec3d& offset,
                         uint32_t seed) {
  std::vector<float> out(p.size());
  gradient_noise({points(p).from(0), int(p.size()), scale, offset, seed}, out.data());
  return out;
}

// Points on the globe (metres, as NoiseField passes them) at wavelengths of 17 m to 300 km, a few
// exactly on lattice nodes and halfway between, and lattice coordinates beyond 2^31 and below 0
// (where the cell wraps), up to 2^50: the AVX2 path gives the same bits as the portable one, for
// any count (8 at a time and a padded rest).
TEST(GradientNoise, SameBitsOnBothPaths) {
  if (!gradient_noise_has_avx2()) GTEST_SKIP() << "this processor has no AVX2: one path only";
  std::vector<Vec3d> p;
  for (int k = 0; k < 4099; ++k) {
    const double a = 0.001 * k, b = 0.37 * std::sin(0.0137 * k);
    p.push_back({6.37e6 * std::cos(a) * std::cos(b), 6.37e6 * std::sin(a) * std::cos(b),
                 6.37e6 * std::sin(b)});
  }
  for (int k = -20; k < 20; ++k) p.push_back({k * 0.5, -k * 0.25, k * 1.0});
  p.push_back({3e9, -3e9, 5e9 + 0.75});
  p.push_back({0x1p50 + 0.25, -0x1p50 + 0.5, 0x1p49 - 0.75});
  const Points axes = points(p);
  for (const double scale : {1 / 17.0, 1 / 50.0, 1 / 300.0, 1 / 3e5, 1.0})
    for (const uint32_t seed : {0u, 1u, 0xdeadbeefu}) {
      const GradientNoiseInput in{axes.from(0), int(p.size()), scale, {0.37, 0.74, 1.11}, seed};
      std::vector<float> portable(p.size()), avx2(p.size());
      gradient_noise_portable(in, portable.data());
      gradient_noise_avx2(in, avx2.data());
      for (size_t k = 0; k < p.size(); ++k)
        ASSERT_EQ(std::bit_cast<uint32_t>(avx2[k]), std::bit_cast<uint32_t>(portable[k]))
            << "point " << k << " scale " << scale << " seed " << seed;
      for (const int n : {1, 7, 9}) {  // fewer than 8 points, or a padded rest
        float v[9];
        gradient_noise_avx2({axes.from(0), n, scale, in.offset, seed}, v);
        for (int k = 0; k < n; ++k)
          ASSERT_EQ(std::bit_cast<uint32_t>(v[k]), std::bit_cast<uint32_t>(portable[size_t(k)]))
              << n << " points";
      }
    }
}

// Gradient noise: 0 at every lattice node, and its gradient there, by finite differences, one of
// Perlin's 12 cube-edge vectors (two components +-1, one 0), all 12 used about equally (4 of them
// twice as often: 16 hashed cases). Another seed gives other gradients.
TEST(GradientNoise, EdgeGradientsAtTheNodes) {
  constexpr double kStep = 1.0 / 1024;
  std::map<std::array<int, 3>, int> count;
  int differ = 0;
  for (int k = 0; k < 1200; ++k) {
    const Vec3d node{double(k % 11) - 5, double(k / 11 % 13) + 1e6, -double(k / 143) * 7};
    const std::vector<Vec3d> p{node,
                               {node[0] + kStep, node[1], node[2]},
                               {node[0], node[1] + kStep, node[2]},
                               {node[0], node[1], node[2] + kStep}};
    const std::vector<float> v = noise(p, 1, {}, 42), other = noise(p, 1, {}, 43);
    ASSERT_EQ(v[0], 0) << k;
    std::array<int, 3> g{};
    int nonzero = 0;
    for (int a = 0; a < 3; ++a) {
      const double d = v[size_t(a) + 1] / kStep;
      g[size_t(a)] = int(std::lround(d));
      ASSERT_NEAR(d, g[size_t(a)], 1e-3) << k << " axis " << a;
      ASSERT_LE(std::abs(g[size_t(a)]), 1);
      nonzero += g[size_t(a)] != 0;
      differ += std::abs(other[size_t(a) + 1] - v[size_t(a) + 1]) > 1e-6f;
    }
    ASSERT_EQ(nonzero, 2) << k;
    ++count[g];
  }
  ASSERT_EQ(count.size(), 12u);
  for (const auto& [g, n] : count) {  // 1/16 or 2/16 of 1200: 75 or 150
    const bool repeated = g == std::array{1, 1, 0} || g == std::array{-1, 1, 0} ||
                          g == std::array{0, -1, 1} || g == std::array{0, -1, -1};
    EXPECT_NEAR(n, repeated ? 150 : 75, repeated ? 45 : 30) << g[0] << g[1] << g[2];
  }
  EXPECT_GT(differ, 1200);  // most nodes, most axes
}

// Codomain [-1, 1], used; the same value 2^32 nodes further along each axis (the period) and
// 2^50 nodes away (the largest lattice coordinates), and continuity across a lattice plane.
TEST(GradientNoise, RangePeriodAndContinuity) {
  std::vector<Vec3d> p, shifted;
  for (int k = 0; k < 20000; ++k) {
    p.push_back({k * 0.125, k % 7 * 0.375 - 100, k % 13 * 0.625});
    shifted.push_back({p.back()[0] + 4294967296.0, p.back()[1] - 4294967296.0, p.back()[2]});
  }
  // Quarter nodes, exact 2^50 away too (the ulp there is 1/4).
  std::vector<Vec3d> quarter, far;
  for (const Vec3d& x : p) {
    quarter.push_back(
        {std::round(4 * x[0]) / 4, std::round(4 * x[1]) / 4, std::round(4 * x[2]) / 4});
    far.push_back(
        {quarter.back()[0] + 0x1p50, quarter.back()[1] - 0x1p50, quarter.back()[2] + 0x1p50});
  }
  const std::vector<float> v = noise(p, 1, {}, 7), w = noise(shifted, 1, {}, 7),
                           q = noise(quarter, 1, {}, 7), f = noise(far, 1, {}, 7);
  float lo = 1, hi = -1;
  for (size_t k = 0; k < p.size(); ++k) {
    ASSERT_EQ(v[k], w[k]) << k;
    ASSERT_EQ(q[k], f[k]) << k;
    lo = std::min(lo, v[k]), hi = std::max(hi, v[k]);
  }
  EXPECT_GE(lo, -1);
  EXPECT_LE(hi, 1);
  EXPECT_LT(lo, -0.5);
  EXPECT_GT(hi, 0.5);
  const std::vector<float> across = noise(
      {{3 - 1e-7, 0.3, 0.6}, {3 + 1e-7, 0.3, 0.6}, {0.2, 5 - 1e-7, 0.6}, {0.2, 5 + 1e-7, 0.6}}, 1,
      {}, 7);
  EXPECT_NEAR(across[0], across[1], 1e-5);
  EXPECT_NEAR(across[2], across[3], 1e-5);
}

}  // namespace
}  // namespace maquette::texture
