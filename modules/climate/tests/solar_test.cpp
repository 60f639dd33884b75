// climate.solar against closed forms: the daily extraterrestrial integral on a horizontal plane,
// the equivalence of a south-facing slope at latitude phi with a horizontal plane at
// phi - slope, the operator on a tilted plane, and shadows behind a synthetic ridge.
#include <gtest/gtest.h>

#include <cmath>

#include "../sun.h"
#include "climate_module.h"

namespace maquette::climate {
namespace {

using climate_test::centre_of;
using climate_test::east_m;
using climate_test::north_m;
using climate_test::run;
using climate_test::with_halo;

constexpr double kRad = M_PI / 180;

// Daily extraterrestrial irradiation on a horizontal plane (Wh/m^2), e.g. Duffie & Beckman 1.10.3.
double analytic_day(double lat_deg, int day, double solar_constant) {
  const double lat = lat_deg * kRad, d = declination(day);
  const double ws = std::acos(std::clamp(-std::tan(lat) * std::tan(d), -1.0, 1.0));
  return 24 / M_PI * solar_constant * eccentricity(day) *
         (std::cos(lat) * std::cos(d) * std::sin(ws) + ws * std::sin(lat) * std::sin(d));
}

SolarOptions clear(int first, int last, double minutes) {
  SolarOptions o;
  o.transmissivity = 1;
  o.first_day = first;
  o.last_day = last;
  o.minutes = minutes;
  return o;
}

TEST(Sun, HorizontalPlaneMatchesTheExtraterrestrialIntegral) {
  for (const double lat : {0.0, 23.0, 46.0, -35.0}) {
    SCOPED_TRACE(lat);
    const SolarOptions o = clear(1, 365, 2);
    double expected = 0;
    for (int day = 1; day <= 365; ++day) expected += analytic_day(lat, day, 1367);
    const double got = SolarModel(o).radiation(lat, 0, 0, 0);
    EXPECT_NEAR(got / expected, 1, 2e-5);
  }
  // Day sampling: every 5th day weighted by 5 stays within 0.1 % over a year at the equator.
  SolarOptions coarse = clear(1, 365, 15);
  coarse.day_step = 5;
  double year = 0;
  for (int day = 1; day <= 365; ++day) year += analytic_day(0, day, 1367);
  EXPECT_NEAR(SolarModel(coarse).radiation(0, 0, 0, 0) / year, 1, 1e-3);
}

TEST(Sun, SouthSlopeEqualsHorizontalPlaneNearerTheEquator) {
  // While the declination is positive the sun is above the horizon whenever it is in front of
  // the slope, so the integrands are identical.
  const SolarOptions o = clear(100, 240, 10);
  const SolarModel model(o);
  for (const double slope : {10.0, 25.0, 40.0}) {
    const double phi = 46;
    const double tilted = model.radiation(phi, 0, std::tan(slope * kRad), 0);
    const double level = model.radiation(phi - slope, 0, 0, 0);
    EXPECT_NEAR(tilted / level, 1, 1e-12) << slope;
    // Facing north instead: far less.
    EXPECT_LT(model.radiation(phi, 0, -std::tan(slope * kRad), 0), tilted);
  }
}

TEST(Sun, AtmosphereAttenuatesLessAtAltitude) {
  SolarOptions o = clear(1, 365, 15);
  o.transmissivity = 0.7;
  const SolarModel model(o);
  const double sea = model.radiation(40, 0, 0, 0);
  const double high = model.radiation(40, 0, 0, 3000);
  const double top = SolarModel(clear(1, 365, 15)).radiation(40, 0, 0, 0);
  EXPECT_LT(sea, high);
  EXPECT_LT(high, top);
  EXPECT_GT(sea / top, 0.4);
  EXPECT_LT(sea / top, 0.7);
}

constexpr int kSize = 64;
const CellId kCell = CellId::FromFaceColRow(2, 10, 300, 40);  // ~140 m pixels, about 40 N

// Operator on a plane rising 30 degrees towards the south-east (facing north-west): its centre
// pixel matches the closed form for that gradient and latitude, with or without shadow search.
TEST(SolarOperator, TiltedPlane) {
  const LonLat origin = centre_of(kCell, kSize, kSize / 2, kSize / 2);
  const double ge = 0.35, gn = -0.45;  // rise per metre east, north
  const auto plane = [&](LonLat p) {
    return 1000 + ge * east_m(p, origin) + gn * north_m(p, origin);
  };
  CellData data;
  data.inputs.emplace("dem", with_halo(kCell, kSize, 64, plane));
  const json params = {{"transmissivity", 0.75}, {"day_step", 10}, {"minutes", 20}};
  const CellData open = run(
      "climate.solar", kCell, kSize, data,
      {{"transmissivity", 0.75}, {"day_step", 10}, {"minutes", 20}, {"max_shadow_distance", 0}});
  const CellData shaded = run("climate.solar", kCell, kSize, data, params);
  SolarOptions o;
  o.transmissivity = 0.75;
  o.day_step = 10;
  o.minutes = 20;
  const double expected = SolarModel(o).radiation(origin.lat, ge, gn, 1000);
  const float got = open.outputs.at("radiation").at(kSize / 2, kSize / 2);
  EXPECT_NEAR(got / expected, 1, 2e-3);
  // A plane shades nothing but itself, which the incidence angle already accounts for.
  EXPECT_NEAR(shaded.outputs.at("radiation").at(kSize / 2, kSize / 2) / got, 1, 2e-3);
}

// An east-west ridge 2 km high: in winter its north foot lies in its shadow, its south foot
// does not.
TEST(SolarOperator, RidgeCastsShadowNorthward) {
  const LonLat origin = centre_of(kCell, kSize, kSize / 2, kSize / 2);
  const auto ridge = [&](LonLat p) {
    const double y = north_m(p, origin) / 1500;
    return 2000 * std::exp(-y * y);
  };
  CellData data;
  data.inputs.emplace("dem", with_halo(kCell, kSize, 64, ridge));
  const json winter = {{"first_day", 1}, {"last_day", 40}, {"day_step", 4}, {"minutes", 20}};
  json open_params = winter;
  open_params["max_shadow_distance"] = 0;
  const CellData with = run("climate.solar", kCell, kSize, data, winter);
  const CellData without = run("climate.solar", kCell, kSize, data, open_params);
  const Tile<float>& shaded = with.outputs.at("radiation");
  const Tile<float>& open = without.outputs.at("radiation");
  int north_row = -1, south_row = -1;
  for (int row = 0; row < kSize; ++row) {
    const double y = north_m(centre_of(kCell, kSize, kSize / 2, row), origin);
    if (north_row < 0 && y < 2500) north_row = row;  // rows run southwards
    if (y > -2500) south_row = row;
  }
  const int c = kSize / 2;
  RecordProperty("latitude", std::to_string(origin.lat));
  EXPECT_LT(shaded.at(c, north_row), 0.2 * open.at(c, north_row));
  EXPECT_NEAR(shaded.at(c, south_row) / open.at(c, south_row), 1, 1e-3);
  EXPECT_GT(open.at(c, south_row), 0);
}

}  // namespace
}  // namespace maquette::climate
