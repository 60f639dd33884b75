// The regions D_spread may prefer (spread_regions.h) on a hand-built level of five 8 x 8 regions
// side by side, grey: regions 0-3 of label 0 at 0.1, 0.2, 0.395 and 0.4 (region 2's first two
// pixels excluded and white), region 4 of label 1 at 0.9. Label 0's 254 allowed pixels take their
// region's mean, so by mid-ranks region 0's quantile is 32 / 254, region 1's 96 / 254, region 2's
// 159 / 254 and region 3's 222 / 254: in 255ths 32, 96, 160 and 223; region 4 is label 1's only
// one (0.5: 128). Counted, the white pixels would lift region 2's mean to 0.414, above region 3's,
// and swap the two.
#include "../spread_regions.h"

#include <gtest/gtest.h>

#include <vector>

namespace maquette::synthesis {
namespace {

constexpr int kSide = 1 << kSpreadRegionShift, kRegions = 5;

ExemplarLevel five_regions() {
  ExemplarLevel e;
  e.width = kSide * kRegions;
  e.height = kSide;
  const float grey[kRegions] = {0.1f, 0.2f, 0.395f, 0.4f, 0.9f};
  for (int y = 0; y < e.height; ++y)
    for (int x = 0; x < e.width; ++x) {
      const int region = x / kSide;
      e.labels.push_back(region == 4 ? 1 : 0);
      for (int c = 0; c < 3; ++c) e.rgb.push_back(grey[region]);
    }
  e.excluded.assign(e.labels.size(), 0);
  for (const int x : {2 * kSide, 2 * kSide + 1}) {
    const size_t white = size_t(e.index(x, 0));
    e.excluded[white] = 1;
    for (int c = 0; c < 3; ++c) e.rgb[3 * white + size_t(c)] = 1.0f;
  }
  return e;
}

// The quantile of region r's allowed pixels, all equal, or -1.
int region_value(const std::vector<uint8_t>& quantiles, const ExemplarLevel& e, int r) {
  int value = -1;
  for (int y = 0; y < e.height; ++y)
    for (int x = r * kSide; x < (r + 1) * kSide; ++x) {
      const size_t i = size_t(e.index(x, y));
      if (e.excluded[i]) continue;
      if (value >= 0 && value != quantiles[i]) return -1;
      value = quantiles[i];
    }
  return value;
}

TEST(SpreadRegions, EachRegionsLightnessIsItsQuantileAmongItsClasssRegions) {
  const ExemplarLevel e = five_regions();
  const auto q = region_quantiles(e);
  ASSERT_EQ(q.size(), e.labels.size());
  const int expected[kRegions] = {32, 96, 160, 223, 128};  // region 2: the white pixels not counted
  for (int r = 0; r < kRegions; ++r) EXPECT_EQ(region_value(q, e, r), expected[r]) << r;
  EXPECT_EQ(q[size_t(e.index(2 * kSide, 0))], 128);  // an excluded pixel
  // The central 60 %: quantiles [0.2, 0.8] (51 to 204 255ths); all of them with 1.
  const bool central[kRegions] = {false, true, true, false, true};
  for (int r = 0; r < kRegions; ++r) {
    EXPECT_EQ(typical_region(q[size_t(e.index(r * kSide + 3, 3))], 0.6), central[r]) << r;
    EXPECT_TRUE(typical_region(q[size_t(e.index(r * kSide + 3, 3))], 1.0)) << r;
  }
  EXPECT_TRUE(typical_region(51, 0.6));
  EXPECT_FALSE(typical_region(50, 0.6));
  EXPECT_TRUE(typical_region(204, 0.6));
  EXPECT_FALSE(typical_region(205, 0.6));
}

// A region holding two classes: each class's pixels take the mean of the region's pixels of that
// class, not of the region's.
TEST(SpreadRegions, EachClassOfARegionHasItsOwnMean) {
  ExemplarLevel e = five_regions();
  // Region 4's left half becomes label 0 at 0.25: label 0's 286 allowed pixels are 64 at 0.1,
  // 64 at 0.2, these 32 at 0.25, 62 at 0.395 and 64 at 0.4 (a mean over the whole region, 0.575,
  // would be the class's lightest): these at 144 / 286, region 3 at 254 / 286.
  for (int y = 0; y < e.height; ++y)
    for (int x = 4 * kSide; x < 4 * kSide + kSide / 2; ++x) {
      const size_t i = size_t(e.index(x, y));
      e.labels[i] = 0;
      for (int c = 0; c < 3; ++c) e.rgb[3 * i + size_t(c)] = 0.25f;
    }
  const auto q = region_quantiles(e);
  EXPECT_EQ(q[size_t(e.index(4 * kSide, 3))], 128);              // 128.4
  EXPECT_EQ(q[size_t(e.index(4 * kSide + kSide - 1, 3))], 128);  // label 1's one region
  EXPECT_EQ(region_value(q, e, 3), 226);                         // 226.5
}

}  // namespace
}  // namespace maquette::synthesis
