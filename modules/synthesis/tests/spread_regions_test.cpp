// The regions D_spread may prefer (spread_regions.h) on a hand-built level of five 8 x 8 regions
// side by side, grey: regions 0-3 of label 0 at 0.1, 0.2, 0.395 and 0.4 (region 2's first pixel
// excluded and white), region 4 of label 1 at 0.9. Label 0's 255 allowed pixels take their
// region's mean, so by mid-ranks region 0's quantile is 32 / 255 = 0.125, region 1's 96 / 255 =
// 0.376, region 2's 159.5 / 255 = 0.625 and region 3's 223 / 255 = 0.875; region 4 is label 1's
// only one (0.5). Counted, the white pixel would lift region 2's mean to 0.4045, above region 3's,
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
  const size_t white = size_t(e.index(2 * kSide, 0));
  e.excluded[white] = 1;
  for (int c = 0; c < 3; ++c) e.rgb[3 * white + size_t(c)] = 1.0f;
  return e;
}

// The quantile of region r's allowed pixels, all equal, or -1.
float region_value(const std::vector<float>& quantiles, const ExemplarLevel& e, int r) {
  float value = -1;
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
  EXPECT_FLOAT_EQ(region_value(q, e, 0), float(32.0 / 255));
  EXPECT_FLOAT_EQ(region_value(q, e, 1), float(96.0 / 255));
  EXPECT_FLOAT_EQ(region_value(q, e, 2), float(159.5 / 255));  // the white pixel not counted
  EXPECT_FLOAT_EQ(region_value(q, e, 3), float(223.0 / 255));
  EXPECT_FLOAT_EQ(region_value(q, e, 4), 0.5f);       // its class's one region: the median
  EXPECT_EQ(q[size_t(e.index(2 * kSide, 0))], 0.5f);  // the excluded pixel
  // The central 60 %: quantiles [0.2, 0.8]; all of them with 1.
  const bool central[kRegions] = {false, true, true, false, true};
  for (int r = 0; r < kRegions; ++r) {
    EXPECT_EQ(typical_region(region_value(q, e, r), 0.6), central[r]) << r;
    EXPECT_TRUE(typical_region(region_value(q, e, r), 1.0)) << r;
  }
}

// A region holding two classes: each class's pixels take the mean of the region's pixels of that
// class, not of the region's.
TEST(SpreadRegions, EachClassOfARegionHasItsOwnMean) {
  ExemplarLevel e = five_regions();
  // Region 4's left half becomes label 0 at 0.25: label 0's 287 allowed pixels are 64 at 0.1,
  // 64 at 0.2, these 32 at 0.25, 63 at 0.395 and 64 at 0.4 (a mean over the whole region, 0.575,
  // would be the class's lightest).
  for (int y = 0; y < e.height; ++y)
    for (int x = 4 * kSide; x < 4 * kSide + kSide / 2; ++x) {
      const size_t i = size_t(e.index(x, y));
      e.labels[i] = 0;
      for (int c = 0; c < 3; ++c) e.rgb[3 * i + size_t(c)] = 0.25f;
    }
  const auto q = region_quantiles(e);
  EXPECT_FLOAT_EQ(q[size_t(e.index(4 * kSide, 3))], float(144.0 / 287));
  EXPECT_FLOAT_EQ(q[size_t(e.index(4 * kSide + kSide - 1, 3))], 0.5f);  // label 1's one region
  EXPECT_FLOAT_EQ(region_value(q, e, 3), float(255.0 / 287));
}

}  // namespace
}  // namespace maquette::synthesis
