// texture.calibrate against Landsat 8's published rescaling (reflectance = (2e-5 DN - 0.1) /
// sin(sun elevation), USGS Landsat 8 Data Users Handbook, section 5) and the sRGB standard's
// transfer function (IEC 61966-2-1: code 128 is linear 0.2158605), computed by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "texture_module.h"

namespace maquette::texture_test {
namespace {

const CellId kCell = CellId::FromFaceColRow(0, 3, 1, 1);
constexpr int kSize = 4;

// Landsat 8's coefficients for every band, the sun at 60 degrees.
json landsat8(const json& extra = json::object()) {
  json p = {{"reflectance_mult", {2e-5, 2e-5, 2e-5}},
            {"reflectance_add", {-0.1, -0.1, -0.1}},
            {"sun_elevation", 60}};
  p.update(extra);
  return p;
}

// Runs the operator on a tile whose band b holds dn[b] at every pixel; pixel (0, 0) of every
// band is missing (NaN).
Tile<float> calibrated(const std::array<float, 3>& dn, const json& params) {
  CellData data;
  const char* names[] = {"red", "green", "blue"};
  for (int b = 0; b < 3; ++b) {
    Tile<float> t(kSize, 1);
    for (int r = 0; r < kSize; ++r)
      for (int c = 0; c < kSize; ++c) t.at(c, r) = dn[size_t(b)];
    t.at(0, 0) = NAN;
    data.inputs.emplace(names[b], std::move(t));
  }
  return run_cell("texture.calibrate", kCell, kSize, std::move(data), params).outputs.at("rgb");
}

TEST(Calibrate, ReflectanceHazeAndSrgbByHand) {
  // Red: DN 10000 is reflectance 0.1 / sin 60 = 0.11547; the dark object DN 6000 is 0.023094,
  // so the haze is 0.013094 (1 % left to the dark object); (0.11547 - 0.013094) / 0.3 = 0.34125
  // linear is sRGB 255 (1.055 0.34125^(1 / 2.4) - 0.055) = 157.86 -> 158.
  // Green: DN 8371.10 is linear 0.2158605 above the same haze: code 128.
  // Blue: below its haze -> 1 (0 is nodata); far above white -> 255 is the red of the second run.
  const Tile<float> t = calibrated(
      {10000, 8371.1f, 6000}, landsat8({{"dark_object_dn", {6000, 6000, 9000}}, {"white", 0.3}}));
  EXPECT_EQ(t.at(1, 1, 0), 158);
  EXPECT_EQ(t.at(3, 2, 1), 128);
  EXPECT_EQ(t.at(2, 3, 2), 1);
  for (int b = 0; b < 3; ++b) EXPECT_TRUE(std::isnan(t.at(0, 0, b)));  // missing stays missing
  const Tile<float> bright = calibrated({40000, 5000, 5000}, landsat8());
  EXPECT_EQ(bright.at(1, 1, 0), 255);
  EXPECT_EQ(bright.at(1, 1, 1), 1);  // negative reflectance (below the offset) clamps
}

TEST(Calibrate, WithoutDarkObjectNoHazeIsRemoved) {
  // Linear 0.11547 / 0.3 = 0.3849 -> sRGB 255 (1.055 0.3849^(1 / 2.4) - 0.055) = 166.70 -> 167.
  const Tile<float> t = calibrated({10000, 10000, 10000}, landsat8());
  for (int b = 0; b < 3; ++b) EXPECT_EQ(t.at(2, 2, b), 167) << b;
}

TEST(Calibrate, ACoefficientPerBandIsRequired) {
  json two = landsat8();
  two["reflectance_mult"] = {2e-5, 2e-5};
  try {
    calibrated({1, 1, 1}, two);
    FAIL() << "two coefficients for three bands were accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("params.reflectance_mult: expected at least 3 items"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace maquette::texture_test
