// The light guide of the transfer in the picture (light_guide.h, paint_panorama.h's
// panorama_light, maquette-paint's painting_light and w_light), on panorama_scene.h's scene with
// rolling hills on the plateau and the plain, so that each class has slopes in light and in
// shade. Checked: the quantiles by hand on small cases; raising w_light lowers the light
// mismatch; the effect itself, against an oracle computed here: within each class, the rank
// correlation (Spearman) of the target's shading and the lightness of the painting pixel each
// output pixel copies (the painting's relative luminance from its sRGB bytes, whose ranks are
// those of L*) is clearly positive with w_light and about 0 without.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>

#include "../light_guide.h"
#include "panorama_scene.h"

namespace maquette::synthesis {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

TEST(LightGuide, ClassQuantilesByHand) {
  // Class 0 counts 3, 1, 2, 2 (the NaN is not counted): ranks 1 of 4 -> 0.125, the tie of 2
  // and 3 -> 0.5, the 3 -> 0.875. Class 1 counts the 5 alone: 0.5; its 7, not counted, is above
  // every counted value: 1. Class 2 has no counted pixel: NaN.
  const std::vector<float> values = {3, 1, 2, 2, kNaN, 5, 7, 4};
  const std::vector<uint8_t> classes = {0, 0, 0, 0, 0, 1, 1, 2};
  const std::vector<uint8_t> counted = {1, 1, 1, 1, 1, 1, 0, 0};
  const std::vector<float> q = class_quantiles(values, classes, counted);
  const std::vector<float> expected = {0.875f, 0.125f, 0.5f, 0.5f, kNaN, 0.5f, 1.0f, kNaN};
  ASSERT_EQ(q.size(), expected.size());
  for (size_t i = 0; i < q.size(); ++i)
    if (std::isnan(expected[i]))
      EXPECT_TRUE(std::isnan(q[i])) << i;
    else
      EXPECT_FLOAT_EQ(q[i], expected[i]) << i;
}

TEST(LightGuide, PaintingLightnessByHand) {
  // Label 0 allows black, mid grey (twice) and white: L* 0 < 53.6 < 100, quantiles 1/8, the
  // tie 1/2, 7/8; its excluded light grey (L* 81) lies above three of the four: 3/4. Label 1 is
  // all excluded: 0.5. Label 2's one allowed saturated blue (L* 32) and yellow (L* 97): the
  // blue darker, 1/4 and 3/4, whatever its larger blue component.
  Exemplar e;
  e.width = 8, e.height = 1;
  e.rgb = {0,   0,   0,   128, 128, 128, 255, 255, 255, 128, 128, 128,
           200, 200, 200, 10,  10,  10,  0,   0,   255, 255, 255, 0};
  e.labels = {0, 0, 0, 0, 0, 1, 2, 2};
  e.excluded = {0, 0, 0, 0, 1, 1, 0, 0};
  const std::vector<float> light = painting_light(e, painting_lightness(e));
  const std::vector<float> expected = {0.125f, 0.5f, 0.875f, 0.5f, 0.75f, 0.5f, 0.25f, 0.75f};
  ASSERT_EQ(light.size(), expected.size());
  for (size_t i = 0; i < light.size(); ++i) EXPECT_FLOAT_EQ(light[i], expected[i]) << i;
  // A grey image's values take the same quantiles: only their order within a label counts (a
  // dark-toned image is not darker light), and NaN takes 0.5.
  const std::vector<float> grey = {0.1f, 0.2f, 0.3f, 0.2f, 0.25f, kNaN, 0.9f, 0.95f};
  const std::vector<float> from_grey = painting_light(e, grey);
  const std::vector<float> grey_expected = {0.125f, 0.5f, 0.875f, 0.5f, 0.75f, 0.5f, 0.25f, 0.75f};
  for (size_t i = 0; i < from_grey.size(); ++i)
    EXPECT_FLOAT_EQ(from_grey[i], grey_expected[i]) << i;
}

TEST(LightGuide, PanoramaLightByHand) {
  // Forest (41 -> class 1) at shading 0.5 and 0.9: 0.25, 0.75; shrub (52 -> class 0) twice at
  // 0.3: the tie, 0.5 each; a land cover without a class (7) alone: 0.5; the sky: NaN, also
  // where its shading is finite (only the distance says sky), and not counted among the shrub.
  PanoramaPicture p;
  p.width = 7, p.height = 1;
  p.land_cover = {41, 41, 52, 52, 7, kNaN, 52};
  p.distance = {100, 200, 300, 400, 500, kNaN, kNaN};
  p.shading = {0.5f, 0.9f, 0.3f, 0.3f, 0.6f, kNaN, 0.1f};
  PaintParams params;
  params.classes = {{41, 1}, {52, 0}};
  const std::vector<float> light = panorama_light(p, params);
  const std::vector<float> expected = {0.25f, 0.75f, 0.5f, 0.5f, 0.5f};
  ASSERT_EQ(light.size(), 7u);
  for (size_t i = 0; i < expected.size(); ++i) EXPECT_FLOAT_EQ(light[i], expected[i]) << i;
  EXPECT_TRUE(std::isnan(light[5]));
  EXPECT_TRUE(std::isnan(light[6]));
}

// Hills of 150 m and about 3 km across, on the plateau and the plain.
double hills(double lon, double lat) {
  return 150 * std::sin(lon * 2 * M_PI / 0.04) * std::sin(lat * 2 * M_PI / 0.03);
}

const Scene& lit_scene() {
  static const Scene s(hills);
  return s;
}

nlohmann::json lit_params(double w_light) {
  nlohmann::json params = lit_scene().params();
  params["painting_light"] = "lightness";
  params["w_light"] = w_light;
  return params;
}

// Mean |target light - the painting's light at the source| over the terrain.
double light_mismatch(const PaintedPanorama& p, const PanoramaPicture& picture,
                      const nlohmann::json& raw) {
  const PaintParams params = paint_params(raw, "params.json");
  const std::vector<float> target = panorama_light(picture, params);
  const ExemplarLevel& e = transfer_exemplar(params.exemplar)->pyramid.levels[0];
  double sum = 0;
  size_t n = 0;
  for (size_t i = 0; i < target.size(); ++i) {
    if (std::isnan(target[i])) continue;
    const auto [x, y] = source_of(p, i);
    sum += std::abs(double(target[i]) - double(e.light[size_t(e.index(x, y))])), ++n;
  }
  return sum / double(n);
}

TEST(PaintLight, RaisingTheLightWeightLowersTheLightMismatch) {
  const PanoramaPicture picture = read_panorama(lit_scene().picture, true);
  double previous = INFINITY;
  for (const double w : {0.0, 2.0, 8.0}) {
    const nlohmann::json params = lit_params(w);
    const double mismatch = light_mismatch(paint(lit_scene(), params), picture, params);
    std::printf("w_light %g: mean light mismatch %.4f\n", w, mismatch);
    EXPECT_LT(mismatch, previous) << "w_light " << w;
    previous = mismatch;
  }
}

// Ranks 0..n-1 of `v`, ties their mean rank.
std::vector<double> ranks(const std::vector<double>& v) {
  std::vector<size_t> order(v.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return v[a] < v[b]; });
  std::vector<double> out(v.size());
  for (size_t i = 0; i < order.size();) {
    size_t j = i;
    while (j < order.size() && v[order[j]] == v[order[i]]) ++j;
    for (size_t k = i; k < j; ++k) out[order[k]] = 0.5 * double(i + j - 1);
    i = j;
  }
  return out;
}

// Spearman's rank correlation: Pearson's of the ranks.
double spearman(const std::vector<double>& a, const std::vector<double>& b) {
  const std::vector<double> ra = ranks(a), rb = ranks(b);
  const double mean = 0.5 * double(a.size() - 1);
  double ab = 0, aa = 0, bb = 0;
  for (size_t i = 0; i < ra.size(); ++i) {
    ab += (ra[i] - mean) * (rb[i] - mean);
    aa += (ra[i] - mean) * (ra[i] - mean);
    bb += (rb[i] - mean) * (rb[i] - mean);
  }
  return ab / std::sqrt(aa * bb);
}

// The painting's relative luminance at (x, y) from its sRGB bytes (IEC 61966-2-1): L* is a
// monotone function of it, so its ranks are L*'s.
double luminance(const Scene& s, int x, int y) {
  const auto linear = [](uint8_t v) {
    const double c = v / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
  };
  const uint8_t* p = &s.painting[3 * (size_t(y) * kPaintingWidth + size_t(x))];
  return 0.2126 * linear(p[0]) + 0.7152 * linear(p[1]) + 0.0722 * linear(p[2]);
}

// Per land cover (41 forest, 52 shrub), Spearman's correlation of the target's shading and the
// source's luminance over the terrain pixels of that land cover.
std::array<double, 2> shading_lightness_correlation(const PaintedPanorama& p,
                                                    const PanoramaPicture& picture) {
  std::array<double, 2> out{};
  for (const int land : {41, 52}) {
    std::vector<double> shading, lightness;
    for (size_t i = 0; i < picture.shading.size(); ++i) {
      if (std::isnan(picture.distance[i]) || picture.land_cover[i] != land) continue;
      const auto [x, y] = source_of(p, i);
      shading.push_back(picture.shading[i]);
      lightness.push_back(luminance(lit_scene(), x, y));
    }
    out[land == 41 ? 0 : 1] = spearman(shading, lightness);
  }
  return out;
}

TEST(PaintLight, TheCopiedLightnessFollowsTheShadingWithinEachClass) {
  const PanoramaPicture picture = read_panorama(lit_scene().picture, true);
  for (const double w : {0.0, 1.0, 2.0}) {
    const auto rho = shading_lightness_correlation(paint(lit_scene(), lit_params(w)), picture);
    std::printf(
        "w_light %g: Spearman's rho of shading and source lightness: forest %.3f, "
        "shrub %.3f\n",
        w, rho[0], rho[1]);
    for (const double r : rho) {
      if (w == 0) {
        EXPECT_LT(std::abs(r), 0.1) << "w_light 0";
      } else {
        EXPECT_GE(r, 0.5) << "w_light " << w;
      }
    }
  }
}

}  // namespace
}  // namespace maquette::synthesis
