// Colour classification (paper 5.2.1): grey rule, hue boxes that wrap, the snow rule, the
// land-cover exclusion, automatic k-means clusters; and CIEDE2000 against Sharma et al.'s data.
#include <gtest/gtest.h>

#include "../colour.h"
#include "texture_module.h"

namespace maquette::texture {
namespace {

using namespace texture_test;

const CellId kCell = CellId::FromFaceColRow(2, 10, 520, 500);

// A 4 x 4 image: rows of red, dark green, white, grey.
Tile<float> image() {
  const float colours[4][3] = {{200, 30, 20}, {30, 90, 40}, {245, 245, 250}, {120, 120, 118}};
  Tile<float> t(4, 3);
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      for (int k = 0; k < 3; ++k) t.at(c, r, k) = colours[r][k];
  return t;
}

Tile<float> classify(CellData d, const json& params) {
  return run_cell("texture.classify", kCell, 4, std::move(d), params).outputs.at("classes");
}

const json kBoxes = json::parse(R"({"boxes": [
  {"id": 1, "hue": [340, 20], "saturation": [0.5, 1]},
  {"id": 2, "hue": [90, 180]},
  {"id": 3, "hue": [290, 310], "value": [0.8, 1]},
  {"id": 4, "hue": [290, 310]}]})");

TEST(Classify, BoxesWrapAndGreyGetsItsHue) {
  CellData d;
  d.inputs.emplace("rgb", image());
  const Tile<float> k = classify(d, kBoxes);
  EXPECT_EQ(k.at(0, 0), 1);  // red: hue ~3 degrees, in the wrapping box [340, 20]
  EXPECT_EQ(k.at(0, 1), 2);
  EXPECT_EQ(k.at(0, 2), 3);  // white: grey, hue 300, bright
  EXPECT_EQ(k.at(0, 3), 4);  // grey: hue 300, dark
  json no_grey = kBoxes;
  no_grey["grey_threshold"] = 0;
  EXPECT_TRUE(std::isnan(classify(d, no_grey).at(0, 2)));  // hue of white is blue: no box
}

TEST(Classify, SnowBelowMinimalAltitudeAndExcludedLandCover) {
  CellData d;
  d.inputs.emplace("rgb", image());
  Tile<float> dem(4, 1, 0, 3000), lc(4, 1, 0, 42);
  for (int r = 0; r < 4; ++r) dem.at(0, r) = 1000, lc.at(3, r) = 82;
  d.inputs.emplace("dem", dem);
  d.inputs.emplace("landcover", lc);
  json p = kBoxes;
  p["snow_class"] = 3;
  p["snow_min_altitude_m"] = 2000;
  p["exclude_landcover"] = {82, 21};
  const Tile<float> k = classify(d, p);
  EXPECT_TRUE(std::isnan(k.at(0, 2)));  // white at 1000 m: cloud
  EXPECT_EQ(k.at(1, 2), 3);             // white at 3000 m: snow
  EXPECT_EQ(k.at(1, 0), 1);
  for (int r = 0; r < 4; ++r) EXPECT_TRUE(std::isnan(k.at(3, r)));  // cultivated
}

// Majority filter (minimum mapping unit): a red 4 x 4 tile with a ring of 2 beyond it, a green
// pixel inside, a green pair on the border, a grey (unclassified) pixel.
TEST(Classify, MajorityFilter) {
  Tile<float> rgb(4, 3, 2);
  for (int r = -2; r < 6; ++r)
    for (int c = -2; c < 6; ++c) rgb.at(c, r, 0) = 200, rgb.at(c, r, 1) = 30, rgb.at(c, r, 2) = 20;
  const auto paint = [&](int c, int r, std::array<float, 3> v) {
    for (int k = 0; k < 3; ++k) rgb.at(c, r, k) = v[size_t(k)];
  };
  paint(1, 1, {30, 90, 40});
  paint(3, 3, {30, 90, 40});
  paint(4, 3, {30, 90, 40});  // in the ring: counts, but is not output
  paint(2, 0, {120, 120, 118});
  const json boxes =
      json::parse(R"({"boxes": [{"id": 1, "hue": [340, 20]}, {"id": 2, "hue": [90, 180]}]})");
  CellData d;
  d.inputs.emplace("rgb", rgb);
  const Tile<float> none = classify(d, boxes);
  EXPECT_EQ(none.at(1, 1), 2);
  json p = boxes;
  p["majority_radius"] = 1;
  const Tile<float> k = classify(d, p);
  EXPECT_EQ(k.at(1, 1), 1);             // 8 red neighbours of 8 classified
  EXPECT_EQ(k.at(3, 3), 1);             // 2 green of 9 (one from the ring)
  EXPECT_TRUE(std::isnan(k.at(2, 0)));  // unclassified stays unclassified
  EXPECT_EQ(k.at(0, 0), 1);
  // Ties keep the pixel's own class: around (1, 1), 4 red, 4 green (its own) and a grey.
  CellData t;
  paint(1, 1, {30, 90, 40});
  paint(2, 1, {30, 90, 40});
  paint(0, 2, {30, 90, 40});
  paint(1, 2, {30, 90, 40});
  paint(2, 2, {120, 120, 118});
  t.inputs.emplace("rgb", rgb);
  EXPECT_EQ(classify(t, p).at(1, 1), 2);
  p["majority_radius"] = 3;
  try {
    classify(d, p);
    FAIL();
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(),
                 "texture.classify: inputs.rgb: halo 2 is narrower than params.majority_radius 3");
  }
}

TEST(Classify, ErrorsNameTheParameter) {
  CellData d;
  d.inputs.emplace("rgb", image());
  try {
    classify(d, json::object());
    FAIL();
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(),
                 "texture.classify: params: give \"boxes\" or \"centres\" (e.g. from "
                 "texture.cluster)");
  }
  json p = kBoxes;
  p["snow_class"] = 3;
  try {
    classify(d, p);
    FAIL();
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "texture.classify: params.snow_class needs inputs.dem");
  }
}

TEST(Cluster, KMeansFindsTheColoursAndClassifies) {
  const auto run = [] {
    return run_reduce("texture.cluster", {kCell}, 4,
                      [](CellId) {
                        CellData d;
                        d.inputs.emplace("rgb", image());
                        return d;
                      },
                      {{"k", 3}});
  };
  const json clusters = run();
  EXPECT_EQ(clusters, run());
  const json& c = clusters.at("centres");
  ASSERT_EQ(c.size(), 3u);
  for (const auto& z : c) EXPECT_GT(z["pixels"].get<int>(), 0);
  // Red, green and the two greys (same hue 300, low saturation) fall in three clusters.
  CellData d;
  d.inputs.emplace("rgb", image());
  const Tile<float> k = classify(d, {{"centres", c}});
  EXPECT_NE(k.at(0, 0), k.at(0, 1));
  EXPECT_NE(k.at(0, 0), k.at(0, 2));
  EXPECT_NE(k.at(0, 1), k.at(0, 2));
  EXPECT_EQ(k.at(0, 2), k.at(0, 3));
  EXPECT_EQ(k.at(0, 0), k.at(3, 0));
}

// Test pairs 1, 7, 17 and 25 of Sharma, Wu and Dalal (2005).
TEST(Colour, Ciede2000ReferenceValues) {
  EXPECT_NEAR(ciede2000({50, 2.6772, -79.7751}, {50, 0, -82.7485}), 2.0425, 1e-4);
  EXPECT_NEAR(ciede2000({50, 0, 0}, {50, -1, 2}), 2.3669, 1e-4);
  EXPECT_NEAR(ciede2000({50, 2.5, 0}, {73, 25, -18}), 27.1492, 1e-4);
  EXPECT_NEAR(ciede2000({60.2574, -34.0099, 36.2677}, {60.4626, -34.1751, 39.4387}), 1.2644, 1e-4);
  const auto white = srgb_to_lab(255, 255, 255);
  EXPECT_NEAR(white[0], 100, 1e-3);
  EXPECT_NEAR(white[1], 0, 1e-2);
}

}  // namespace
}  // namespace maquette::texture
