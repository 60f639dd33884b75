// fill_basin and water_level (water_body.h) against an analytic paraboloid basin and against
// GRASS r.lake (benchmarks/deform/rlake.sh, a separate process) on the same DEM: identical wet
// mask, the volume equal to the discrete sum of r.lake's depths, and a leak where r.lake's lake
// leaves the stroke.
#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "water_basins.h"

namespace maquette::deform {
namespace {

TEST(WaterBody, ParaboloidVolumeWithinHalfAPercentOfTheClosedForm) {
  const Basin b = paraboloid();
  const double level = 100;  // the shore at radius sqrt(1000 * 100) = 316 m
  const WaterBody body = fill_basin(b.raster(), level);
  ASSERT_FALSE(body.leak);
  // z = r^2 / a with a = 1000: V = pi a h^2 / 2, area pi a h.
  const double a = 1000;
  EXPECT_NEAR(body.volume_m3, std::numbers::pi * a * level * level / 2,
              0.005 * std::numbers::pi * a * level * level / 2);
  EXPECT_NEAR(body.area_m2, std::numbers::pi * a * level, 0.005 * std::numbers::pi * a * level);
  double sum = 0;
  for (size_t k = 0; k < body.wet.size(); ++k) {
    sum += level - double(b.terrain[size_t(body.wet[k])]);
    EXPECT_LT(b.terrain[size_t(body.wet[k])], level);
  }
  EXPECT_NEAR(body.volume_m3, sum, 1e-6 * sum);
}

TEST(WaterBody, SpillLevelIsTheLowestBoundaryHeight) {
  const Basin b = paraboloid();
  double lowest = INFINITY;
  for (int r = 0; r < b.height; ++r)
    for (int c = 0; c < b.width; ++c) {
      const size_t i = size_t(r) * size_t(b.width) + size_t(c);
      bool edge = false;  // a neighbour outside the region or off the grid
      for (int dr = -1; dr <= 1; ++dr)
        for (int dc = -1; dc <= 1; ++dc) {
          const int nr = r + dr, nc = c + dc;
          edge = edge || nr < 0 || nr >= b.height || nc < 0 || nc >= b.width ||
                 !b.inside[size_t(nr) * size_t(b.width) + size_t(nc)];
        }
      if (b.inside[i] && edge) lowest = std::min(lowest, double(b.terrain[i]));
    }
  EXPECT_EQ(water_level(b.raster(), {}), lowest);
  // The disk's rim, in its last ring of pixels (1.5 pixels wide on a diagonal).
  EXPECT_GT(lowest, 448.5 * 448.5 / 1000);
  EXPECT_LE(lowest, 450.0 * 450.0 / 1000);
  EXPECT_GT(water_level(b.raster(), {WaterLevel::Rule::Percentile, 90}), lowest);
  const WaterBody body = fill_basin(b.raster(), lowest);
  EXPECT_FALSE(body.leak);
  EXPECT_GT(body.area_m2, std::numbers::pi * 440 * 440);
}

TEST(WaterBody, LevelAboveTheRimLeaks) {
  const Basin b = paraboloid();
  const double level = 250;  // the rim is at 202.5 m
  const WaterBody body = fill_basin(b.raster(), level);
  ASSERT_TRUE(body.leak);
  EXPECT_FALSE(b.inside[size_t(*body.leak)]);
  // Where the water crosses the stroke: beside an inside pixel below the level, not anywhere the
  // outside water reaches (here the disk below 250 m touches the raster's first row, ~50 m out).
  const int row = int(*body.leak / b.width), col = int(*body.leak % b.width);
  bool beside_the_lake = false;
  for (int r = std::max(row - 1, 0); r <= std::min(row + 1, b.height - 1); ++r)
    for (int c = std::max(col - 1, 0); c <= std::min(col + 1, b.width - 1); ++c) {
      const size_t at = size_t(r) * size_t(b.width) + size_t(c);
      beside_the_lake = beside_the_lake || (b.inside[at] && b.terrain[at] < level);
    }
  EXPECT_TRUE(beside_the_lake) << "leak at column " << col << ", row " << row;
  EXPECT_TRUE(body.wet.empty());
  EXPECT_EQ(body.volume_m3, 0);
}

TEST(WaterBody, LevelFromAttributes) {
  using R = WaterLevel::Rule;
  EXPECT_EQ(WaterLevel::from_attributes({}, "f").rule, R::Spill);
  EXPECT_EQ(WaterLevel::from_attributes({{"level", 12.5}}, "f").value, 12.5);
  const WaterLevel p = WaterLevel::from_attributes({{"level_rule", "percentile:10"}}, "f");
  EXPECT_EQ(p.rule, R::Percentile);
  EXPECT_EQ(p.value, 10);
  for (const auto& bad :
       {nlohmann::json{{"level_rule", "percentile:110"}}, nlohmann::json{{"level_rule", "median"}},
        nlohmann::json{{"level_rule", "percentile:5x"}}, nlohmann::json{{"level", "high"}}}) {
    try {
      WaterLevel::from_attributes(bad, "feature 7 (tool water)");
      ADD_FAILURE() << "accepted " << bad.dump();
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("feature 7 (tool water): field 'level"),
                std::string::npos)
          << e.what();
      EXPECT_NE(std::string(e.what()).find(bad.begin()->dump()), std::string::npos) << e.what();
    }
  }
}

// The pixels below `level` 8-connected to `seed` (a breadth-first flood, the oracle), flagged.
std::vector<uint8_t> flood(const Basin& b, double level, int64_t seed) {
  std::vector<uint8_t> wet(b.terrain.size(), 0);
  std::vector<int64_t> queue{seed};
  wet[size_t(seed)] = 1;
  for (size_t head = 0; head < queue.size(); ++head) {
    const int64_t col = queue[head] % b.width, row = queue[head] / b.width;
    for (int64_t r = std::max<int64_t>(row - 1, 0); r <= std::min<int64_t>(row + 1, b.height - 1);
         ++r)
      for (int64_t c = std::max<int64_t>(col - 1, 0); c <= std::min<int64_t>(col + 1, b.width - 1);
           ++c) {
        const size_t j = size_t(r * b.width + c);
        if (!wet[j] && b.terrain[j] < level) wet[j] = 1, queue.push_back(int64_t(j));
      }
  }
  return wet;
}

// A channel winding down 120 rows (many of the fill's strips of rows), each turn joined by
// diagonal steps only, beside pockets just one dry row or column away; the lake against the
// oracle's flood, and with two outlets cut through the stroke its leak: the first crossing of
// the stroke in row-major order. The first outlet's water runs on outside, along the raster's
// first row, to column 5: the leak is where it crosses (row 0, column 19, beside the outlet at
// row 1, column 20), not the first outside pixel it reaches (column 5, the rule before).
TEST(WaterBody, WindingChannelAsTheFloodFillsIt) {
  Basin b{40, 120, 1.0, {}, {}};
  b.terrain.assign(size_t(b.width) * size_t(b.height), 10.0f);
  b.inside.assign(b.terrain.size(), 0);
  for (int r = 1; r + 1 < b.height; ++r)
    for (int c = 1; c + 1 < b.width; ++c) b.inside[size_t(r * b.width + c)] = 1;
  const auto low = [&](int c, int r) {
    b.terrain[size_t(r * b.width + c)] = float((c * 7 + r * 3) % 5);
  };
  for (int r = 2; r < b.height - 2; r += 4) {
    for (int c = 2; c < b.width - 2; ++c) low(c, r);
    const bool right = r / 4 % 2 == 0;  // the turn: a diagonal zigzag to the next corridor
    const int c = right ? b.width - 3 : 2, in = right ? 1 : -1;
    if (r + 4 < b.height - 2) low(c + in, r + 1), low(c, r + 2), low(c + in, r + 3);
    low(right ? 4 : b.width - 5, r + 2);  // a pocket: one dry row from the corridors
  }
  const double level = 6;
  const WaterBody body = fill_basin(b.raster(), level);
  ASSERT_FALSE(body.leak);
  const std::vector<uint8_t> oracle = flood(b, level, body.seed);
  std::vector<int64_t> wet;
  for (size_t i = 0; i < oracle.size(); ++i)
    if (oracle[i]) wet.push_back(int64_t(i));
  EXPECT_EQ(body.wet, wet);
  EXPECT_GT(body.wet.size(), size_t(29 * 36));  // every corridor, not the pockets
  for (size_t k = 0; k < body.wet.size(); ++k)
    EXPECT_EQ(body.depth[k], float(level - double(b.terrain[size_t(body.wet[k])])));

  low(0, 62), low(1, 62);                   // an outlet to the raster's left edge
  low(20, 1);                               // one from the first corridor to the first row,
  for (int c = 5; c <= 20; ++c) low(c, 0);  // which carries the water on to column 5
  const WaterBody leaking = fill_basin(b.raster(), level);
  ASSERT_TRUE(leaking.leak);
  EXPECT_EQ(*leaking.leak, 19);
  EXPECT_TRUE(leaking.wet.empty());
}

// r.lake's depths (NaN: dry) at `level` from the seed pixel.
std::vector<double> rlake(const Basin& b, double level, int64_t seed) {
  // One directory per test: ctest runs the tests of this file in parallel.
  const std::string dir = testing::TempDir() + "/water_rlake_" +
                          testing::UnitTest::GetInstance()->current_test_info()->name();
  std::filesystem::create_directories(dir);
  EXPECT_TRUE(write_geotiff(b, dir + "/dem.tif"));
  char x[64], y[64], l[64];
  std::snprintf(x, sizeof x, "%.3f", kX0 + (double(seed % b.width) + 0.5) * kPixelM);
  std::snprintf(y, sizeof y, "%.3f", kY0 - (double(seed / b.width) + 0.5) * kPixelM);
  std::snprintf(l, sizeof l, "%.9g", level);
  const std::string cmd = std::string(MAQUETTE_SOURCE_DIR) + "/benchmarks/deform/rlake.sh " + dir +
                          "/dem.tif " + dir + "/lake.tif " + l + " " + x + " " + y;
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  const std::unique_ptr<GDALDataset> ds(
      GDALDataset::Open((dir + "/lake.tif").c_str(), GDAL_OF_RASTER));
  std::vector<double> depth(size_t(b.width) * size_t(b.height), NAN);
  if (!ds) return depth;
  GDALRasterBand* band = ds->GetRasterBand(1);
  EXPECT_EQ(band->RasterIO(GF_Read, 0, 0, b.width, b.height, depth.data(), b.width, b.height,
                           GDT_Float64, 0, 0),
            CE_None);
  int has = 0;
  const double nodata = band->GetNoDataValue(&has);
  for (double& d : depth)
    if (has && d == nodata) d = NAN;
  return depth;
}

// GRASS is an oracle that scripts/setup.sh installs (grass-core): without it these tests fail,
// unless MAQUETTE_SKIP_GRASS=1 asks to skip them.
class WaterBodyGrass : public testing::Test {
 protected:
  void SetUp() override {
    if (std::system("command -v grass >/dev/null 2>&1") == 0) return;
    const char* skip = std::getenv("MAQUETTE_SKIP_GRASS");
    if (skip && std::string(skip) == "1")
      GTEST_SKIP() << "no GRASS here and MAQUETTE_SKIP_GRASS=1: the r.lake oracle is not run";
    FAIL() << "no GRASS (the r.lake oracle): scripts/setup.sh installs grass-core; set "
              "MAQUETTE_SKIP_GRASS=1 to skip this test";
  }
};

TEST_F(WaterBodyGrass, SameLakeAsRLake) {
  const Basin b = hills();
  const double level = water_level(b.raster(), {});
  const WaterBody body = fill_basin(b.raster(), level);
  ASSERT_FALSE(body.leak);
  ASSERT_GT(body.wet.size(), 10000u);
  const std::vector<double> theirs = rlake(b, level, body.seed);
  std::vector<uint8_t> ours(theirs.size(), 0);
  for (const int64_t i : body.wet) ours[size_t(i)] = 1;
  size_t differ = 0;
  double sum = 0;
  for (size_t i = 0; i < theirs.size(); ++i) {
    const bool wet = !std::isnan(theirs[i]) && theirs[i] > 0;
    differ += wet != bool(ours[i]);
    if (wet) sum += theirs[i];
  }
  EXPECT_EQ(differ, 0u) << "of " << body.wet.size() << " wet pixels";
  EXPECT_NEAR(body.volume_m3, sum * kPixelM * kPixelM, 1e-6 * sum * kPixelM * kPixelM);
  for (size_t k = 0; k < body.wet.size(); ++k)
    EXPECT_NEAR(body.depth[k], theirs[size_t(body.wet[k])], 1e-4);
}

TEST_F(WaterBodyGrass, LeakWhereRLakeLeavesTheStroke) {
  const Basin b = hills();
  const double level = water_level(b.raster(), {WaterLevel::Rule::Percentile, 50});
  const WaterBody body = fill_basin(b.raster(), level);
  ASSERT_TRUE(body.leak);
  const std::vector<double> theirs = rlake(b, level, body.seed);
  EXPECT_TRUE(theirs[size_t(*body.leak)] > 0);  // r.lake's water is there too, outside
  EXPECT_FALSE(b.inside[size_t(*body.leak)]);
}

}  // namespace
}  // namespace maquette::deform
