// texture.landcover_share: shares counted by hand and against a direct count over each window
// (the operator sums with a summed-area table), pixels without land cover, the ring beyond the
// tile, errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "texture_module.h"

namespace maquette::texture {
namespace {

using namespace texture_test;

Tile<float> share(const Tile<float>& landcover, const json& params) {
  CellData d;
  d.inputs.emplace("landcover", landcover);
  return run_cell("texture.landcover_share", CellId::FromFaceColRow(0, 4, 3, 5), 4, std::move(d),
                  params)
      .output("share");
}

// A 4 x 4 tile of shrub (52) with a ring of 2: barren land (31) at (0, 0), at (3, 2) and in the
// ring at (-1, 0) and (4, 3); grassland (71) at (2, 1); no land cover at (1, 3) and all of ring
// row -2.
Tile<float> landcover() {
  Tile<float> lc(4, 1, 2);
  for (int r = -2; r < 6; ++r)
    for (int c = -2; c < 6; ++c) lc.at(c, r) = r == -2 ? NAN : 52;
  lc.at(0, 0) = lc.at(3, 2) = lc.at(-1, 0) = lc.at(4, 3) = 31;
  lc.at(2, 1) = 71;
  lc.at(1, 3) = NAN;
  return lc;
}

TEST(LandcoverShare, ByHand) {
  const Tile<float> s = share(landcover(), json::parse(R"({"codes": [31], "radius": 1})"));
  EXPECT_FLOAT_EQ(s.at(0, 0), 2.0f / 9);  // itself and (-1, 0)
  EXPECT_FLOAT_EQ(s.at(3, 3), 2.0f / 9);  // (3, 2) and (4, 3) in the ring
  EXPECT_FLOAT_EQ(s.at(1, 1), 1.0f / 9);  // (0, 0)
  EXPECT_FLOAT_EQ(s.at(2, 2), 1.0f / 8);  // (3, 2) of the 8 known: (1, 3) has none
  EXPECT_FLOAT_EQ(s.at(1, 0), 1.0f / 9);  // (0, 0)
  const Tile<float> two = share(landcover(), json::parse(R"({"codes": [31, 71], "radius": 1})"));
  EXPECT_FLOAT_EQ(two.at(2, 2), 2.0f / 8);  // (3, 2) and (2, 1)
  const Tile<float> own = share(landcover(), json::parse(R"({"codes": [31], "radius": 0})"));
  EXPECT_EQ(own.at(0, 0), 1);
  EXPECT_EQ(own.at(1, 0), 0);
  EXPECT_TRUE(std::isnan(own.at(1, 3)));  // no land cover in its window of one pixel
}

TEST(LandcoverShare, EveryPixelAgainstADirectCount) {
  const Tile<float> lc = landcover();
  const Tile<float> s = share(lc, json::parse(R"({"codes": [31, 71], "radius": 2})"));
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      int known = 0, counted = 0;
      for (int y = r - 2; y <= r + 2; ++y)
        for (int x = c - 2; x <= c + 2; ++x)
          if (!std::isnan(lc.at(x, y))) ++known, counted += lc.at(x, y) == 31 || lc.at(x, y) == 71;
      EXPECT_FLOAT_EQ(s.at(c, r), float(double(counted) / known)) << c << ", " << r;
    }
}

TEST(LandcoverShare, Errors) {
  try {
    share(landcover(), json::parse(R"({"codes": [31], "radius": 3})"));
    FAIL();
  } catch (const Error& e) {
    EXPECT_STREQ(
        e.what(),
        "texture.landcover_share: inputs.landcover: halo 2 is narrower than params.radius 3");
  }
  EXPECT_THROW(share(landcover(), json::parse(R"({"codes": [300]})")), Error);
  EXPECT_THROW(share(landcover(), json::parse(R"({"codes": []})")), Error);
  EXPECT_THROW(share(landcover(), json::parse(R"({"radius": 1})")), Error);
}

}  // namespace
}  // namespace maquette::texture
