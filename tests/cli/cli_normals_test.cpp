// Normal layers stored compactly (codec normal_oct, framework/store/normal_oct.h) through the real
// program on real terrain: terrain.derive on the Zion SRTM writes its normals as normal_oct and its
// slope and aspect as lossless float32; the normals exported to a GeoTIFF and read with GDAL are
// unit vectors within 0.04 degrees of the normals rebuilt from the exported slope and aspect
// (float32: exact to ~1e-5 degrees), in under a quarter of the bytes zstd gives those float
// normals (4.7x fewer at these 35 m pixels; the Zion example's 8.8 m texture normals, smoother
// from pixel to pixel, take 10.3x fewer: benchmarks/README.md, "Normals"). Skipped when the data is
// absent.
#include <gdal.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "run_cli.h"
#include "store/codec.h"
#include "store/store.h"

namespace maquette::test {
namespace {

using json = nlohmann::json;

const std::string kSrtm = std::string(MAQUETTE_SHARED_DIR) + "/data/zion/srtm.tif";
constexpr double kDegrees = 180 / std::numbers::pi;

// The bands of a GeoTIFF as float32, band after band.
std::vector<float> read_bands(const std::string& path, int expected_bands, int& width,
                              int& height) {
  const GDALDatasetH ds = GDALOpen(path.c_str(), GA_ReadOnly);
  EXPECT_NE(ds, nullptr) << path;
  if (ds == nullptr) return {};
  width = GDALGetRasterXSize(ds);
  height = GDALGetRasterYSize(ds);
  EXPECT_EQ(GDALGetRasterCount(ds), expected_bands) << path;
  std::vector<float> v(size_t(width) * size_t(height) * size_t(expected_bands));
  for (int b = 0; b < expected_bands; ++b) {
    const GDALRasterBandH band = GDALGetRasterBand(ds, b + 1);
    EXPECT_EQ(GDALGetRasterDataType(band), GDT_Float32) << path;
    EXPECT_EQ(GDALRasterIO(band, GF_Read, 0, 0, width, height,
                           v.data() + size_t(b) * size_t(width) * size_t(height), width, height,
                           GDT_Float32, 0, 0),
              CE_None);
  }
  GDALClose(ds);
  return v;
}

// Ingests the Zion SRTM into `store` and derives its slope, aspect and normals.
void write_derive_pipeline(const std::string& path, const std::string& store) {
  const json pipeline = {
      {"store", store},
      {"region", {{"bbox", {-113.10, 37.25, -112.98, 37.35}}}},
      {"level", 10},
      {"steps",
       {{{"op", "ingest"},
         {"outputs", {{"layer", "dem"}}},
         {"params", {{"sources", {kSrtm}}, {"as", "dem"}, {"resampling", "cubic"}}}},
        {{"op", "terrain.derive"},
         {"inputs", {{"dem", "dem"}}},
         {"outputs", {{"slope", "slope"}, {"aspect", "aspect"}, {"normal", "normal"}}}}}}};
  std::ofstream(path) << pipeline.dump(1);
}

TEST(CliNormals, DeriveStoresNormalsCompactlyWithinFourHundredthsOfADegree) {
  if (!std::filesystem::exists(kSrtm)) GTEST_SKIP() << "no " << kSrtm;
  const std::string dir = temp_dir();
  write_derive_pipeline(dir + "/p.json", dir + "/z.mqt");
  const CliResult r = run_maquette("-q run " + dir + "/p.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;

  const CliResult info = run_maquette("info " + dir + "/z.mqt --json");
  ASSERT_EQ(info.exit_code, 0) << info.err;
  const json listed = json::parse(info.out);  // a temporary would die before the loop's body
  for (const json& l : listed["layers"])
    EXPECT_EQ(l["codec"], l["name"] == "normal" ? "normal_oct" : "zstd") << l.dump();

  for (const char* layer : {"normal", "slope", "aspect"}) {
    const CliResult e = run_maquette("export gtiff " + dir + "/z.mqt --layer " + layer + " " + dir +
                                     "/" + layer + ".tif");
    ASSERT_EQ(e.exit_code, 0) << e.err;
  }
  GDALAllRegister();
  int w = 0, h = 0, ws = 0, hs = 0, wa = 0, ha = 0;
  const std::vector<float> normal = read_bands(dir + "/normal.tif", 3, w, h);
  const std::vector<float> slope = read_bands(dir + "/slope.tif", 1, ws, hs);
  const std::vector<float> aspect = read_bands(dir + "/aspect.tif", 1, wa, ha);
  ASSERT_TRUE(w == ws && w == wa && h == hs && h == ha && w > 0);

  // Against the float normals rebuilt from slope and aspect (east, north, up; aspect clockwise
  // from north, NaN where flat).
  const size_t pixels = size_t(w) * size_t(h);
  double max_error = 0, sum = 0;
  size_t count = 0;
  for (size_t i = 0; i < pixels; ++i) {
    const double n[3] = {normal[i], normal[pixels + i], normal[2 * pixels + i]};
    if (std::isnan(slope[i])) {
      ASSERT_TRUE(std::isnan(n[0]) && std::isnan(n[1]) && std::isnan(n[2])) << i;
      continue;
    }
    const double s = slope[i] / kDegrees, a = std::isnan(aspect[i]) ? 0 : aspect[i] / kDegrees;
    const double f[3] = {std::sin(s) * std::sin(a), std::sin(s) * std::cos(a), std::cos(s)};
    ASSERT_NEAR(std::hypot(n[0], n[1], n[2]), 1, 1e-6) << i;
    const double cross =
        std::hypot(n[1] * f[2] - n[2] * f[1], n[2] * f[0] - n[0] * f[2], n[0] * f[1] - n[1] * f[0]);
    const double e = std::atan2(cross, n[0] * f[0] + n[1] * f[1] + n[2] * f[2]) * kDegrees;
    max_error = std::max(max_error, e);
    sum += e;
    ++count;
  }
  ASSERT_GT(count, pixels / 2);
  std::cout << "normal_oct on the Zion SRTM (" << count << " normals): max " << max_error
            << " mean " << sum / double(count) << " degrees\n";
  EXPECT_LE(max_error, 0.04);
  EXPECT_GT(max_error, 0);

  // Bytes: the stored normal tiles against the same (decoded) normals as float32 in zstd.
  const auto store = Store::open(dir + "/z.mqt", Store::Mode::ReadOnly);
  const LayerInfo layer = store->require_layer("normal");
  int64_t stored = 0, as_float = 0;
  for (CellId cell : store->tile_cells("normal")) {
    RawTile tile = *store->get_tile("normal", cell);
    stored += int64_t(encode_tile(tile, parse_codec(layer.codec)).size());
    as_float += int64_t(encode_tile(tile, parse_codec("zstd")).size());
  }
  std::cout << "normal tiles: " << stored << " bytes as normal_oct, " << as_float
            << " as float32 zstd\n";
  EXPECT_LT(stored * 4, as_float);
}

// A store whose normals layer was written before codec normal_oct existed (codec zstd) runs the
// pipeline again: the layer keeps its codec and holds the float normals themselves, the ones a
// new store compresses (encoding them as normal_oct gives that store's tiles).
TEST(CliNormals, NormalsLayerOfAnOlderStoreKeepsItsCodec) {
  if (!std::filesystem::exists(kSrtm)) GTEST_SKIP() << "no " << kSrtm;
  const std::string dir = temp_dir();
  write_derive_pipeline(dir + "/new.json", dir + "/new.mqt");
  ASSERT_EQ(run_maquette("-q run " + dir + "/new.json").exit_code, 0);
  const auto fresh = Store::open(dir + "/new.mqt", Store::Mode::ReadOnly);
  const std::vector<CellId> cells = fresh->tile_cells("normal");
  ASSERT_FALSE(cells.empty());
  {
    // The older store: the same normals layer in zstd, holding (here) the decoded normal_oct tiles.
    const auto old = Store::open(dir + "/old.mqt", Store::Mode::Create);
    LayerInfo info = fresh->require_layer("normal");
    info.codec = "zstd";
    old->create_layer(info);
    for (CellId cell : cells) old->put_tile("normal", cell, *fresh->get_tile("normal", cell));
  }
  write_derive_pipeline(dir + "/old.json", dir + "/old.mqt");
  for (const char* resume : {"", " --resume"}) {
    const CliResult r = run_maquette(std::string("-q run") + resume + " " + dir + "/old.json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  const auto old = Store::open(dir + "/old.mqt", Store::Mode::ReadOnly);
  EXPECT_EQ(old->require_layer("normal").codec, "zstd");
  EXPECT_EQ(old->tile_cells("normal"), cells);
  size_t rewritten = 0;
  for (CellId cell : cells) {
    const RawTile exact = *old->get_tile("normal", cell),
                  compact = *fresh->get_tile("normal", cell);
    EXPECT_EQ(decode_tile(encode_tile(exact, parse_codec("normal_oct"))).bytes, compact.bytes)
        << cell.ToText();
    if (exact.bytes != compact.bytes) ++rewritten;
  }
  EXPECT_EQ(rewritten, cells.size());
}

}  // namespace
}  // namespace maquette::test
