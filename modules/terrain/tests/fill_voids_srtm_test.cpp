// terrain.fill_voids on real SRTM voids (Mt Rainier, 3 arc-second, voids of -32768): every void
// is filled, the Laplace fill stays within each void's border range (maximum principle), and
// known samples masked as artificial voids are recovered with an RMSE well below the relief.
#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <limits>
#include <memory>

#include "../voids.h"
#include "terrain_module.h"

namespace maquette::terrain {
namespace {

using terrain_test::run;

constexpr int kSize = 128, kHalo = 64;
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
const CellId kCell = CellId::FromFaceColRow(2, 7, 10, 10);

// The 128-pixel tile at raster column 256, row 128 (the block with the most voids) with its
// 64-pixel halo, nodata as NaN; nullopt when the shared data is absent.
std::optional<Tile<float>> rainier_window() {
  const std::string path = MAQUETTE_SHARED_DIR "/data/srtm3/mt_rainier_90m.tif";
  if (!std::filesystem::exists(path)) return std::nullopt;
  GDALAllRegister();
  const std::unique_ptr<GDALDataset> ds(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER));
  if (!ds) throw Error("cannot open " + path);
  GDALRasterBand* band = ds->GetRasterBand(1);
  int has_nodata = 0;
  const double nodata = band->GetNoDataValue(&has_nodata);
  Tile<float> tile(kSize, 1, kHalo);
  const int side = tile.stride();
  if (band->RasterIO(GF_Read, 256 - kHalo, 128 - kHalo, side, side, tile.data().data(), side, side,
                     GDT_Float32, 0, 0) != CE_None)
    throw Error("cannot read " + path);
  for (float& v : tile.data())
    if (has_nodata && v == float(nodata)) v = kNaN;
  return tile;
}

CellData input(const Tile<float>& dem) {
  CellData data;
  data.inputs.emplace("dem", dem);
  return data;
}

// Range of the known samples 4-adjacent to a void.
std::pair<float, float> border_range(const Tile<float>& dem, const Void& v) {
  const std::span<const float> data = dem.data();
  float lo = std::numeric_limits<float>::max(), hi = -lo;
  for (const int s : v.samples)
    for (const int n : {s - 1, s + 1, s - dem.stride(), s + dem.stride()})
      if (!std::isnan(data[n])) {
        lo = std::min(lo, data[n]);
        hi = std::max(hi, data[n]);
      }
  return {lo, hi};
}

TEST(FillVoidsSrtm, FillsRainierVoids) {
  const std::optional<Tile<float>> dem = rainier_window();
  if (!dem) GTEST_SKIP() << "no ../shared/data/srtm3/mt_rainier_90m.tif";
  const std::vector<Void> voids = find_voids(*dem);
  size_t samples = 0;
  int largest = 0;
  for (const Void& v : voids) {
    samples += v.samples.size();
    largest = std::max(largest, v.extent);
  }
  std::cout << voids.size() << " voids, " << samples << " samples, largest extent " << largest
            << "\n";
  ASSERT_GT(samples, 500u);
  ASSERT_LE(largest, 63);

  const Tile<float> laplace =
      run("terrain.fill_voids", kCell, kSize, input(*dem), {{"method", "laplace"}})
          .outputs.at("dem");
  const Tile<float> biharmonic =
      run("terrain.fill_voids", kCell, kSize, input(*dem)).outputs.at("dem");
  const int halo = dem->halo(), stride = dem->stride();
  for (const Void& v : voids) {
    const auto [lo, hi] = border_range(*dem, v);
    for (const int s : v.samples) {
      const int col = s % stride - halo, row = s / stride - halo;
      if (col < 0 || row < 0 || col >= kSize || row >= kSize) continue;
      ASSERT_FALSE(std::isnan(biharmonic.at(col, row))) << col << "," << row;
      ASSERT_GE(laplace.at(col, row), lo - 1e-3f) << col << "," << row;
      ASSERT_LE(laplace.at(col, row), hi + 1e-3f) << col << "," << row;
    }
  }
}

// Squares of known samples, away from real voids, masked and filled: RMSE against the truth, for
// both methods, below the spread of the truth inside the squares (what a flat fill at the
// squares' own means would give).
TEST(FillVoidsSrtm, RecoversMaskedSamples) {
  const std::optional<Tile<float>> dem = rainier_window();
  if (!dem) GTEST_SKIP() << "no ../shared/data/srtm3/mt_rainier_90m.tif";
  constexpr int kSide = 9;
  Tile<float> masked = *dem;
  std::vector<std::pair<int, int>> corners;  // top-left of each masked square
  for (int row = 4; row + kSide + 4 <= kSize; row += 2 * kSide)
    for (int col = 4; col + kSide + 4 <= kSize; col += 2 * kSide) {
      bool clear = true;  // no real void within 3 pixels of the square
      for (int r = row - 3; r < row + kSide + 3; ++r)
        for (int c = col - 3; c < col + kSide + 3; ++c) clear = clear && !std::isnan(dem->at(c, r));
      if (!clear) continue;
      corners.emplace_back(col, row);
      for (int r = row; r < row + kSide; ++r)
        for (int c = col; c < col + kSide; ++c) masked.at(c, r) = kNaN;
    }
  ASSERT_GT(corners.size(), 10u);

  double spread = 0;
  for (const auto& [col, row] : corners) {
    double mean = 0;
    for (int r = row; r < row + kSide; ++r)
      for (int c = col; c < col + kSide; ++c) mean += dem->at(c, r);
    mean /= kSide * kSide;
    for (int r = row; r < row + kSide; ++r)
      for (int c = col; c < col + kSide; ++c) spread += std::pow(dem->at(c, r) - mean, 2);
  }
  const double count = double(corners.size()) * kSide * kSide;
  spread = std::sqrt(spread / count);

  for (const std::string method : {"laplace", "biharmonic"}) {
    const Tile<float> filled =
        run("terrain.fill_voids", kCell, kSize, input(masked), {{"method", method}})
            .outputs.at("dem");
    double sum = 0;
    for (const auto& [col, row] : corners)
      for (int r = row; r < row + kSide; ++r)
        for (int c = col; c < col + kSide; ++c) sum += std::pow(filled.at(c, r) - dem->at(c, r), 2);
    const double rmse = std::sqrt(sum / count);
    std::cout << method << ": RMSE " << rmse << " m over " << corners.size() << " squares of "
              << kSide << " px (relief std inside them " << spread << " m)\n";
    RecordProperty(method + "_rmse_m", std::to_string(rmse));
    EXPECT_LT(rmse, 0.5 * spread) << method;
  }
}

}  // namespace
}  // namespace maquette::terrain
