// terrain.synthesize: deterministic, and a function of position only, so tiles meet seamlessly
// across face seams (their halos hold the function evaluated where the halo pixels really lie).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <map>

#include "../synthetic_terrain.h"
#include "terrain_module.h"

namespace maquette::terrain {
namespace {

using terrain_test::run;
using terrain_test::true_centre;

constexpr int kSize = 16;
constexpr int kLevel = 6;

Tile<float> synthesize(CellId cell, const json& params = json::object()) {
  return run("terrain.synthesize", cell, kSize, {}, params).outputs.at("dem");
}

TEST(Synthesize, SameBitsOnRepeatedRuns) {
  const CellId cell = CellId::FromFaceColRow(3, kLevel, 10, 20);
  const Tile<float> a = synthesize(cell), b = synthesize(cell);
  ASSERT_EQ(a.data().size(), b.data().size());
  EXPECT_EQ(std::memcmp(a.data().data(), b.data().data(), a.data().size_bytes()), 0);
  const Tile<float> other = synthesize(cell, {{"seed", 2}});
  EXPECT_NE(std::memcmp(a.data().data(), other.data().data(), a.data().size_bytes()), 0);
}

// Parameters out of range are errors naming the field and the bound, before anything runs.
TEST(Synthesize, ParamsOutOfRange) {
  const json& schema = terrain_test::terrain_operator("terrain.synthesize").spec().params_schema;
  const auto message = [&](const json& params) {
    try {
      validate_params(schema, params, "step 1 (terrain.synthesize)");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(
      message({{"amplitude_m", 30000}}).find("params.amplitude_m: 30000 is above the maximum"),
      std::string::npos);
  EXPECT_NE(message({{"octaves", 0}}).find("params.octaves: 0 is below the minimum 1"),
            std::string::npos);
  EXPECT_NE(message({{"feature_km", 0}}).find("params.feature_km: 0 is below the minimum"),
            std::string::npos);
  EXPECT_EQ(message({{"amplitude_m", 20000}, {"octaves", 24}, {"feature_km", 20000}}), "");
}

// Tiles along an equatorial-polar seam, the R|O seam and around two cube corners: every pixel,
// halo included, equals the function evaluated directly at its true position.
TEST(Synthesize, SeamlessAcrossFaces) {
  const uint32_t last = (1U << kLevel) - 1;
  const json params = {{"seed", 7}, {"feature_km", 900}};
  const TerrainParams direct{7, 2500, 7, 900};
  std::map<CellId, Tile<float>> made;
  const TileFetch fetch = [&](CellId c) {
    auto it = made.find(c);
    if (it == made.end()) it = made.emplace(c, synthesize(c, params)).first;
    return std::optional<Tile<float>>(it->second);
  };
  for (const CellId cell :
       {CellId::FromFaceColRow(1, kLevel, 5, 0), CellId::FromFaceColRow(4, kLevel, last, 9),
        CellId::FromFaceColRow(1, kLevel, 0, 0), CellId::FromFaceColRow(5, kLevel, last, last)}) {
    const Tile<float> tile = assemble_halo(default_grid(), cell, kSize, 4, fetch);
    for (int row = -4; row < kSize + 4; ++row)
      for (int col = -4; col < kSize + 4; ++col) {
        const float expected =
            float(synthetic_elevation(up_unit(true_centre(cell, kSize, col, row)), direct));
        ASSERT_EQ(tile.at(col, row), expected) << cell.ToText() << " " << col << "," << row;
      }
  }
}

TEST(Synthesize, LooksLikeTerrain) {
  // One tile per face at level 2: land and sea, relief of the order of the amplitude.
  int sea = 0, land = 0;
  float highest = 0;
  for (int face = 0; face < 6; ++face)
    for (uint32_t i = 0; i < 4; ++i) {
      const Tile<float> t = synthesize(CellId::FromFaceColRow(face, 2, i, 3 - i));
      for (const float h : t.data()) {
        (h == 0 ? sea : land) += 1;
        highest = std::max(highest, h);
      }
    }
  EXPECT_GT(sea, 0);
  EXPECT_GT(land, 0);
  EXPECT_GT(highest, 1000.0f);
  EXPECT_LT(highest, 10000.0f);
}

}  // namespace
}  // namespace maquette::terrain
