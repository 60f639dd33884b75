// The two paths of the layer kernels (plain C++ and AVX2) against each other, bit for bit, and
// the plain one against the formula by hand.
#include "../layer_kernels.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "../surface.h"

namespace maquette::texture {
namespace {

constexpr size_t kBlocks = 40, kPixels = kBlocks * kBlock;

// A row with every case: parents 0 and covering, missing heights and coordinates (kBins),
// coordinates on and between bin centres and at both ends, tables with zeros.
struct Row {
  std::vector<PaddedTable> tables;
  std::vector<PairTable> pairs;
  std::vector<float> parent, coordinate, noise, product, coverage, rgb;
  std::vector<float> height;
  std::vector<int> dominant;
  std::vector<ConstraintRow> constraints;

  explicit Row(unsigned seed)
      : tables(3),
        parent(kPixels),
        coordinate(kPixels + 1, float(kBins)),  // the third constraint reads it shifted by 1
        noise(kPixels),
        product(kPixels),
        coverage(kPixels),
        rgb(3 * kPixels),
        height(kPixels),
        dominant(kPixels, -1) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> unit(0, 1);
    for (size_t t = 0; t < tables.size(); ++t) {
      Table table;
      for (int i = 0; i < kBins; ++i) table[size_t(i)] = unit(random) < 0.3f ? 0 : unit(random);
      tables[t] = padded(t == 0 ? hat_table({500, 1000, 2000, 2500}, 0, 3000) : table);
      pairs.push_back(pair_table(tables[t]));
    }
    for (size_t c = 0; c < kPixels; ++c) {
      const float u = unit(random);
      parent[c] = u < 0.2f ? 0 : u < 0.4f ? 1 : unit(random);
      coordinate[c] = u < 0.1f ? float(kBins) : table_coordinate(unit(random) * 1.2f - 0.1f);
      height[c] = u > 0.95f ? NAN : unit(random) * 3400 - 200;
      noise[c] = unit(random) * 2 - 1;
      for (size_t k = 0; k < 3; ++k) rgb[3 * c + k] = unit(random) * 255;
    }
    for (size_t c = 0; c < kBlock; ++c) parent[c] = 0;  // a block no layer covers
    constraints = {{pairs[0].data(), nullptr},          // the height's
                   {pairs[1].data(), coordinate.data()},
                   {pairs[2].data(), coordinate.data() + 1}};
  }

  ConstrainRow constrain() {
    return {parent.data(), constraints, height.data(), 1.0f / 3000, 0, product.data()};
  }
  BlendRow blend(const float* n) {
    return {0.6f,
            0.9f,
            2.5f,
            {200, 100, 50},
            3,
            parent.data(),
            product.data(),
            n,
            coverage.data(),
            {&rgb[0], &rgb[kPixels], &rgb[2 * kPixels]},
            height.data(),
            dominant.data()};
  }
};

std::vector<uint16_t> all_blocks() {
  std::vector<uint16_t> b(kBlocks);
  for (size_t i = 0; i < kBlocks; ++i) b[i] = uint16_t(i);
  return b;
}

// Runs both kernels of `k` over the row (the blend over the blocks kept, twice: with noise and
// without), returning the blocks kept.
std::vector<uint16_t> run(const LayerKernels& k, Row& row) {
  std::vector<uint16_t> blocks = all_blocks();
  blocks.resize(k.constrain(row.constrain(), blocks.data(), blocks.size(), blocks.data()));
  k.blend(row.blend(row.noise.data()), blocks.data(), blocks.size());
  k.blend(row.blend(nullptr), blocks.data(), blocks.size());
  return blocks;
}

template <typename T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

TEST(LayerKernels, Avx2SameBitsAsPlain) {
  const LayerKernels* avx2 = avx2_kernels();
  if (!avx2) GTEST_SKIP() << "this CPU has no AVX2";
  for (unsigned seed = 1; seed <= 20; ++seed) {
    Row a(seed), b(seed);
    const std::vector<uint16_t> kept = run(plain_kernels(), a);
    EXPECT_EQ(kept, run(*avx2, b)) << seed;
    EXPECT_GT(kept.size(), 0u);
    EXPECT_LT(kept.size(), kBlocks);  // block 0 has no parent
    EXPECT_TRUE(same_bits(a.product, b.product)) << seed;
    EXPECT_TRUE(same_bits(a.coverage, b.coverage)) << seed;
    EXPECT_TRUE(same_bits(a.rgb, b.rgb)) << seed;
    EXPECT_TRUE(same_bits(a.height, b.height)) << seed;
    EXPECT_EQ(a.dominant, b.dominant) << seed;
  }
}

TEST(LayerKernels, Avx2CoordinatesSameBitsAsPlain) {
  const LayerKernels* avx2 = avx2_kernels();
  if (!avx2) GTEST_SKIP() << "this CPU has no AVX2";
  std::mt19937 random(3);
  std::uniform_real_distribution<float> value(-300, 3300);
  std::vector<float> values(kPixels + 5);  // not whole blocks
  for (float& v : values) v = value(random);
  values[0] = -1000;  // below the range
  values[1] = 5000;   // above
  values[3] = NAN;
  values[kPixels + 2] = NAN;
  std::vector<float> a(values.size()), b(values.size());
  plain_kernels().coordinates(values.data(), values.size(), 1.0f / 3000, 0.1f, a.data());
  avx2->coordinates(values.data(), values.size(), 1.0f / 3000, 0.1f, b.data());
  EXPECT_TRUE(same_bits(a, b));
  for (size_t c = 0; c < values.size(); ++c)
    EXPECT_EQ(a[c], table_coordinate(values[c] * (1.0f / 3000) + 0.1f)) << c;
  EXPECT_EQ(a[0], 0);
  EXPECT_EQ(a[1], float(kBins - 1));
  EXPECT_EQ(a[3], float(kBins));
}

// Pixel by pixel, the formula of surface.h with the lookups of model_test's TableLookupByHand.
TEST(LayerKernels, PlainFollowsTheFormula) {
  Row row(7), before(7);
  const std::vector<uint16_t> kept = run(plain_kernels(), row);
  size_t checked = 0;
  for (const uint16_t block : kept)
    for (size_t c = size_t(block) * kBlock; c < size_t(block + 1) * kBlock; ++c) {
      const float x = table_coordinate(before.height[c] * (1.0f / 3000) + 0);
      const float p = (before.parent[c] > 0 ? 1.0f : 0.0f) * lookup_at(before.tables[0], x) *
                      lookup_at(before.tables[1], before.coordinate[c]) *
                      lookup_at(before.tables[2], before.coordinate[c + 1]);
      EXPECT_EQ(row.product[c], p) << c;
      // The second blend (no noise) overwrote the coverage: bias 0.6 times the product.
      const float cv1 =
          std::clamp((0.6f + 0.9f * before.noise[c]) * p, 0.0f, 1.0f) * before.parent[c];
      const float cv2 = std::clamp(0.6f * p, 0.0f, 1.0f) * before.parent[c];
      EXPECT_EQ(row.coverage[c], cv2) << c;
      float red = (1 - cv1) * before.rgb[c] + cv1 * 200;
      red = (1 - cv2) * red + cv2 * 200;
      EXPECT_EQ(row.rgb[c], red) << c;
      if (!std::isnan(before.height[c])) {
        EXPECT_EQ(row.height[c], before.height[c] + cv1 * 2.5f * before.noise[c]) << c;
      }
      EXPECT_EQ(row.dominant[c], cv1 >= 0.5f || cv2 >= 0.5f ? 3 : -1) << c;
      checked += p > 0;
    }
  EXPECT_GT(checked, 20u);
}

}  // namespace
}  // namespace maquette::texture
