// climate.solar against GRASS r.sun (run as a separate process by
// benchmarks/climate/rsun_beam.sh) on the Zion SRTM DEM through the real program: the clear-sky
// beam irradiation of June 21 with r.sun's atmosphere (Linke turbidity 3, "atmosphere": "linke"),
// half-hour steps and cast shadows, on the same DEM (the store's, exported in UTM zone 12 for
// both). The mean and the median pixel agree within 2 %. Skipped when the data or GRASS is absent.
// Also: the same bits for any thread count and region run.
#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

#include "run_cli.h"

namespace maquette::test {
namespace {

const std::string kZion = std::string(MAQUETTE_SHARED_DIR) + "/data/zion/srtm.tif";
const std::string kBox = "-113.1 37.2 -112.98 37.32";  // Zion Canyon, ~11 x 13 km

std::vector<float> read_band(const std::string& path, int& width, int& height) {
  GDALAllRegister();
  const std::unique_ptr<GDALDataset> ds(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER));
  if (!ds) throw std::runtime_error("cannot open " + path);
  width = ds->GetRasterXSize();
  height = ds->GetRasterYSize();
  std::vector<float> v(size_t(width) * size_t(height));
  GDALRasterBand* band = ds->GetRasterBand(1);
  if (band->RasterIO(GF_Read, 0, 0, width, height, v.data(), width, height, GDT_Float32, 0, 0) !=
      CE_None)
    throw std::runtime_error("cannot read " + path);
  int has = 0;
  const double nodata = band->GetNoDataValue(&has);
  for (float& x : v)
    if (has && x == float(nodata)) x = NAN;
  return v;
}

// Band 1 of two rasters of the same size.
struct BandPair {
  std::vector<float> first, second;
  int width = 0, height = 0;
};
BandPair read_pair(const std::string& first, const std::string& second) {
  BandPair pair;
  int width = 0, height = 0;
  pair.first = read_band(first, pair.width, pair.height);
  pair.second = read_band(second, width, height);
  if (width != pair.width || height != pair.height)
    throw std::runtime_error(first + " and " + second + " differ in size");
  return pair;
}

// climate.solar's clear-sky beam in the r.sun configuration (Linke turbidity 3, half-hour steps)
// over `bbox` into layer `output`, with `params` added.
nlohmann::json solar_pipeline(const std::string& store, const std::vector<double>& bbox,
                              const std::string& output, const nlohmann::json& params) {
  nlohmann::json p = {{"atmosphere", "linke"}, {"linke_turbidity", 3}, {"minutes", 30}};
  p.update(params);
  return {{"store", store},
          {"region", {{"bbox", bbox}}},
          {"level", 0},
          {"steps",
           {{{"op", "climate.solar"},
             {"inputs", {{"dem", "dem"}}},
             {"outputs", {{"radiation", output}}},
             {"params", p}}}}};
}

TEST(SolarRsun, BeamOfJune21MatchesRsunWithin2Percent) {
  if (!std::filesystem::exists(kZion)) GTEST_SKIP() << "no " << kZion;
  if (std::system("command -v grass >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "no GRASS (scripts/setup.sh installs grass-core)";
  const std::string dir = temp_dir(), store = dir + "/zion.mqt";
  CliResult r = run_maquette("--quiet ingest " + store + " " + kZion +
                             " --layer dem --as dem --tile-size 64 --bbox " + kBox);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ofstream(dir + "/solar.json")
      << solar_pipeline(store, {-113.1, 37.2, -112.98, 37.32}, "beam",
                        {{"first_day", 172}, {"last_day", 172}, {"day_step", 1}})
             .dump();
  r = run_maquette("--quiet run " + dir + "/solar.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const std::string layer : {"dem", "beam"}) {
    r = run_maquette("--quiet export gtiff " + store + " " + dir + "/" + layer +
                     ".tif --crs EPSG:32612 --resolution 70 --layer " + layer);
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  const std::string rsun = std::string(MAQUETTE_SOURCE_DIR) + "/benchmarks/climate/rsun_beam.sh " +
                           dir + "/dem.tif " + dir + "/rsun.tif 172 0.5 3 > /dev/null";
  ASSERT_EQ(std::system(rsun.c_str()), 0);

  const BandPair pair = read_pair(dir + "/beam.tif", dir + "/rsun.tif");
  const std::vector<float>& ours = pair.first;
  const std::vector<float>& theirs = pair.second;
  const int w = pair.width, h = pair.height;
  // Pixels at least 10 from the edges, where both have a value (r.sun's slope needs neighbours).
  double sum_ours = 0, sum_theirs = 0;
  std::vector<double> relative;
  for (int y = 10; y < h - 10; ++y)
    for (int x = 10; x < w - 10; ++x) {
      const float a = ours[size_t(y) * size_t(w) + size_t(x)];
      const float b = theirs[size_t(y) * size_t(w) + size_t(x)];
      if (std::isnan(a) || std::isnan(b) || b <= 0) continue;
      sum_ours += a;
      sum_theirs += b;
      relative.push_back(std::abs(a / b - 1));
    }
  ASSERT_GT(relative.size(), 10000u);
  std::nth_element(relative.begin(), relative.begin() + relative.size() / 2, relative.end());
  const double mean_ratio = sum_ours / sum_theirs, median = relative[relative.size() / 2];
  std::cout << relative.size() << " pixels: mean ours / r.sun " << mean_ratio
            << ", median |ours / r.sun - 1| " << median << "\n";
  RecordProperty("mean_ratio", std::to_string(mean_ratio));
  RecordProperty("median_relative_difference", std::to_string(median));
  EXPECT_NEAR(mean_ratio, 1, 0.02);
  EXPECT_LT(median, 0.02);
}

// The horizons' sparse far samples and their shared block marches take nothing from the thread
// count or the region run: the Zion example's summer with 64 directions, over the canyon with
// one thread and over its western half with two, gives the same bits where both ran.
TEST(SolarRsun, SameBitsForAnyThreadCountAndRegion) {
  if (!std::filesystem::exists(kZion)) GTEST_SKIP() << "no " << kZion;
  const std::string dir = temp_dir(), store = dir + "/zion.mqt";
  CliResult r = run_maquette("--quiet ingest " + store + " " + kZion +
                             " --layer dem --as dem --tile-size 64 --bbox " + kBox);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json summer = {
      {"first_day", 152}, {"last_day", 243}, {"day_step", 15}, {"horizon_directions", 64}};
  const std::vector<double> west = {-113.1, 37.2, -113.04, 37.32};
  std::ofstream(dir + "/all.json")
      << solar_pipeline(store, {-113.1, 37.2, -112.98, 37.32}, "all", summer).dump();
  std::ofstream(dir + "/west.json") << solar_pipeline(store, west, "west", summer).dump();
  r = run_maquette("--quiet run " + dir + "/all.json --threads 1");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_maquette("--quiet run " + dir + "/west.json --threads 2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const std::string layer : {"all", "west"}) {
    r = run_maquette("--quiet export gtiff " + store + " " + dir + "/" + layer + ".tif --layer " +
                     layer + " --bbox -113.1 37.2 -113.04 37.32");
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  const BandPair pair = read_pair(dir + "/all.tif", dir + "/west.tif");
  const std::vector<float>& all = pair.first;
  const std::vector<float>& west_half = pair.second;
  size_t compared = 0, different = 0;
  for (size_t i = 0; i < all.size(); ++i) {
    if (std::isnan(all[i]) || std::isnan(west_half[i])) continue;
    ++compared;
    different += all[i] != west_half[i];
  }
  EXPECT_GT(compared, 10000u);
  EXPECT_EQ(different, 0u) << "of " << compared;
}

}  // namespace
}  // namespace maquette::test
