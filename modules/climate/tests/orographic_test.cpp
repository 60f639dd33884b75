// climate.orographic on a synthetic north-south ridge with a west wind: more rain on the
// windward side, less in the lee, and the documented mass balance.
#include <gtest/gtest.h>

#include <cmath>

#include "climate_module.h"

namespace maquette::climate {
namespace {

using climate_test::centre_of;
using climate_test::east_m;
using climate_test::run;
using climate_test::with_halo;

constexpr int kSize = 64;
const CellId kCell = CellId::FromFaceColRow(3, 10, 300, 500);  // ~140 m pixels near the equator

struct Ridge {
  LonLat origin = centre_of(kCell, kSize, kSize / 2, kSize / 2);
  double operator()(LonLat p) const {
    const double x = east_m(p, origin) / 500;
    return 1000 * std::exp(-x * x);
  }
};

CellData inputs() {
  CellData data;
  data.inputs.emplace("dem", with_halo(kCell, kSize, 64, Ridge{}));
  data.inputs.emplace("precipitation", with_halo(kCell, kSize, 64, [](LonLat) { return 800; }));
  return data;
}

const json kParams = {
    {"wind_direction", 270}, {"strength", 0.5}, {"decay_length", 1000}, {"max_distance", 2500}};

TEST(Orographic, WindwardWetterLeeDrier) {
  const CellData out = run("climate.orographic", kCell, kSize, inputs(), kParams);
  const Tile<float>& rain = out.outputs.at("precipitation");
  const Ridge ridge;
  const int row = kSize / 2;
  int windward = -1, lee = -1, east_slope = -1, west_foot = -1;
  for (int col = 0; col < kSize; ++col) {
    const double x = east_m(centre_of(kCell, kSize, col, row), ridge.origin);
    if (x < -300) windward = col;
    if (x < -800) west_foot = col;
    if (lee < 0 && x > 800) lee = col;
    if (east_slope < 0 && x > 300) east_slope = col;
  }
  EXPECT_GT(rain.at(windward, row), 900);
  EXPECT_LT(rain.at(lee, row), 750);
  // Far upwind, flat ground: unchanged.
  EXPECT_NEAR(rain.at(0, row), 800, 1e-3);
  // An east wind mirrors the pattern.
  json east = kParams;
  east["wind_direction"] = 90;
  const CellData other = run("climate.orographic", kCell, kSize, inputs(), east);
  const Tile<float>& mirrored = other.outputs.at("precipitation");
  EXPECT_GT(mirrored.at(east_slope, row), 900);
  EXPECT_LT(mirrored.at(west_foot, row), 750);
}

// The adjustment moves precipitation from the lee to the windward side: over a domain holding
// the ridge and its upwind reach, the total is unchanged.
TEST(Orographic, MassBalance) {
  const CellData out = run("climate.orographic", kCell, kSize, inputs(), kParams);
  const Tile<float>& rain = out.outputs.at("precipitation");
  double moved = 0, gross = 0;
  for (int row = 0; row < kSize; ++row)
    for (int col = 0; col < kSize; ++col) {
      moved += rain.at(col, row) - 800.0;
      gross += std::abs(rain.at(col, row) - 800.0);
    }
  EXPECT_GT(gross, 1e5);
  EXPECT_LT(std::abs(moved) / gross, 1e-3) << moved << " of " << gross;
}

// Flat ground whose data ends inside the tile (no data east of the ridge's crest line): every
// pixel with data keeps its precipitation, those at the edge of the data too (they were 0 when
// the pixel's own term was read by bilinear interpolation, which reaches into the no data).
TEST(Orographic, EdgeOfTheDataKeepsItsPrecipitation) {
  const Ridge ridge;
  const auto flat_west = [&](LonLat p) {
    return east_m(p, ridge.origin) < 0 ? 1500.0 : std::nan("");
  };
  CellData data;
  data.inputs.emplace("dem", with_halo(kCell, kSize, 64, flat_west));
  data.inputs.emplace("precipitation", with_halo(kCell, kSize, 64, [](LonLat) { return 800; }));
  const CellData out = run("climate.orographic", kCell, kSize, data, kParams);
  const Tile<float>& rain = out.outputs.at("precipitation");
  const Tile<float> dem = climate_test::sample(kCell, kSize, flat_west);
  int with_data = 0;
  for (int row = 0; row < kSize; ++row)
    for (int col = 0; col < kSize; ++col) {
      if (std::isnan(dem.at(col, row))) {
        EXPECT_TRUE(std::isnan(rain.at(col, row)));
        continue;
      }
      ++with_data;
      EXPECT_NEAR(rain.at(col, row), 800, 1e-3) << col << ", " << row;
    }
  EXPECT_GT(with_data, kSize);
}

TEST(Orographic, NeedsItsHalo) {
  CellData data;
  data.inputs.emplace("dem", with_halo(kCell, kSize, 1, Ridge{}));
  data.inputs.emplace("precipitation", with_halo(kCell, kSize, 1, [](LonLat) { return 1; }));
  EXPECT_EQ(climate_test::error_of([&] { run("climate.orographic", kCell, kSize, data); }),
            "climate.orographic: input 'dem' of cell " + kCell.ToText() +
                " needs a halo of 64 pixels and tile size 64");
}

}  // namespace
}  // namespace maquette::climate
