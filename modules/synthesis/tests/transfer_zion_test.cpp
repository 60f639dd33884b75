// synthesis.transfer run by the real program on Zion's land cover and DEM (../shared/data) with
// Bruegel's painting and a hand exclusion mask: the same bits on one thread and two; every output
// colour is the painting's (GDAL's own read of it, averaged over the exemplar's block) at the
// source coordinates written beside it; no source lies in the excluded part.
#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/tile.h"
#include "run_cli.h"
#include "store/store.h"
#include "synthetic_raster.h"
#include "zion_ingest.h"

namespace maquette::synthesis {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr int kScale = 4;             // exemplar_scale: a small exemplar keeps the test short
constexpr double kExcludedTop = 0.4;  // the mask excludes the painting's top 40 % of rows

struct TransferRun {
  fs::path dir;
  std::string store;
};

// The painting's pixels, as GDAL reads them (RGB interleaved).
std::vector<uint8_t> painting_rgb(int& width, int& height) {
  GDALAllRegister();
  std::unique_ptr<GDALDataset> ds(GDALDataset::Open(kPainting.c_str(), GDAL_OF_RASTER));
  width = ds->GetRasterXSize();
  height = ds->GetRasterYSize();
  std::vector<uint8_t> rgb(size_t(width) * size_t(height) * 3);
  int bands[3] = {1, 2, 3};
  EXPECT_EQ(ds->RasterIO(GF_Read, 0, 0, width, height, rgb.data(), width, height, GDT_Byte, 3,
                         bands, 3, long(width) * 3, 1, nullptr),
            CE_None);
  return rgb;
}

// A mask of the painting's size, 255 on its top kExcludedTop of rows.
void write_mask(const std::string& path, int width, int height) {
  GDALDriver* mem = GetGDALDriverManager()->GetDriverByName("MEM");
  std::unique_ptr<GDALDataset> ds(mem->Create("", width, height, 1, GDT_Byte, nullptr));
  std::vector<uint8_t> mask(size_t(width) * size_t(height), 0);
  std::fill_n(mask.begin(), size_t(kExcludedTop * height) * size_t(width), uint8_t(255));
  ASSERT_EQ(ds->GetRasterBand(1)->RasterIO(GF_Write, 0, 0, width, height, mask.data(), width,
                                           height, GDT_Byte, 0, 0, nullptr),
            CE_None);
  GDALClose(GetGDALDriverManager()->GetDriverByName("PNG")->CreateCopy(
      path.c_str(), ds.get(), false, nullptr, nullptr, nullptr));
}

// The pipeline run in a fresh folder; `changes` overrides the transfer's params, `inputs` its
// inputs; `then` are steps after it.
TransferRun run_transfer(const std::string& name, int threads, const std::string& mask,
                         const json& changes = json::object(), test::CliResult* result = nullptr,
                         const json& inputs = {{"landcover", "landcover"}, {"dem", "dem"}},
                         const json& then = json::array()) {
  TransferRun run{
      fs::temp_directory_path() / ("maquette-synthesis-" + std::to_string(getpid()) + name), ""};
  fs::remove_all(run.dir);
  fs::create_directories(run.dir);
  run.store = (run.dir / "zion.mqt").string();
  json pipeline = {{"store", run.store},
                   {"region", {{"bbox", {-113.03, 37.25, -112.98, 37.30}}}},
                   {"level", 10},
                   {"steps",
                    {{{"op", "synthesis.transfer"},
                      {"inputs", inputs},
                      {"outputs", {{"rgb", "painted"}, {"source", "painted_source"}}},
                      {"params",
                       {{"painting", kPainting},
                        {"exclusion", mask},
                        {"landcover_classes", {{"3", 5}, {"4", 3}, {"5", 4}, {"6", 2}}},
                        {"altitude_range", {1100, 2700}},
                        {"painting_altitude", "rows"},
                        {"exemplar_scale", kScale}}}}}}};
  const json ingest = zion_ingest_steps();
  pipeline["steps"].insert(pipeline["steps"].begin(), ingest.begin(), ingest.end());
  json& params = pipeline["steps"][2]["params"];
  if (mask.empty()) params.erase("exclusion");
  params.update(changes);
  for (const json& step : then) pipeline["steps"].push_back(step);
  const fs::path path = run.dir / "pipeline.json";
  std::ofstream(path) << pipeline.dump(1);
  const test::CliResult r =
      test::run_maquette("run " + path.string() + " --quiet --threads " + std::to_string(threads));
  if (result)
    *result = r;
  else
    EXPECT_EQ(r.exit_code, 0) << r.err;
  return run;
}

TEST(TransferZion, SameBitsOnOneAndTwoThreadsAndColoursFromTheirSources) {
  if (!fs::exists(kPainting) || !fs::exists(kShared + "/zion/nlcd.tif"))
    GTEST_SKIP() << "../shared/data is absent";
  int width = 0, height = 0;
  const std::vector<uint8_t> painting = painting_rgb(width, height);
  const fs::path mask =
      fs::temp_directory_path() / ("maquette-synthesis-mask-" + std::to_string(getpid()) + ".png");
  write_mask(mask.string(), width, height);
  const TransferRun one = run_transfer("-1", 1, mask.string()),
                    two = run_transfer("-2", 2, mask.string());
  const auto a = Store::open(one.store, Store::Mode::ReadOnly);
  const auto b = Store::open(two.store, Store::Mode::ReadOnly);

  const std::vector<CellId> cells = a->tile_cells("painted");
  ASSERT_GE(cells.size(), 2u);
  ASSERT_EQ(cells, b->tile_cells("painted"));
  size_t pixels = 0, wrong_colour = 0, excluded = 0;
  for (const CellId cell : cells) {
    const RawTile rgb = *a->get_tile("painted", cell);
    EXPECT_EQ(rgb.bytes, b->get_tile("painted", cell)->bytes) << cell.ToText();
    const RawTile raw_source = *a->get_tile("painted_source", cell);
    EXPECT_EQ(raw_source.bytes, b->get_tile("painted_source", cell)->bytes) << cell.ToText();
    const Tile<float> source = to_tile<float>(raw_source);
    ASSERT_EQ(source.channels(), 3);  // column, row, painting
    for (int r = 0; r < source.size(); ++r)
      for (int c = 0; c < source.size(); ++c) {
        if (std::isnan(source.at(c, r, 0))) continue;
        ++pixels;
        EXPECT_EQ(source.at(c, r, 2), 0.0f);  // one painting: always the first
        const int sx = int(source.at(c, r, 0)), sy = int(source.at(c, r, 1));
        excluded += sy < int(std::ceil(kExcludedTop * height));
        for (int k = 0; k < 3; ++k) {
          double mean = 0;
          for (int dy = 0; dy < kScale; ++dy)
            for (int dx = 0; dx < kScale; ++dx)
              mean += painting[(size_t(sy + dy) * size_t(width) + size_t(sx + dx)) * 3 + size_t(k)];
          mean /= kScale * kScale;
          const auto got = double(std::to_integer<uint8_t>(
              rgb.bytes[(size_t(r) * size_t(rgb.size) + size_t(c)) * 3 + size_t(k)]));
          wrong_colour += std::abs(got - mean) > 0.51;
        }
      }
  }
  EXPECT_GT(pixels, 50000u);
  EXPECT_EQ(excluded, 0u);
  EXPECT_EQ(wrong_colour, 0u);
  fs::remove_all(one.dir);
  fs::remove_all(two.dir);
  fs::remove(mask);
}

TEST(TransferZion, AMissingPaintingABadClassTableAndHeightsAsLandCoverAreNamed) {
  if (!fs::exists(kShared + "/zion/nlcd.tif")) GTEST_SKIP() << "../shared/data is absent";
  const auto refused = [](const std::string& name, const json& changes, const json& inputs,
                          const std::string& message) {
    test::CliResult r;
    const TransferRun run = run_transfer(name, 2, "", changes, &r, inputs);
    EXPECT_NE(r.exit_code, 0) << name;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    fs::remove_all(run.dir);
  };
  const json inputs = {{"landcover", "landcover"}, {"dem", "dem"}};
  // A relative path is the working directory's (the pipeline's ingests take the pipeline file's);
  // told when the pipeline is read (exemplar_params_check.h).
  refused("-missing", {{"painting", "no/such/painting.png"}}, inputs,
          "step 3 (synthesis.transfer): no/such/painting.png: the painting (painting): no such "
          "file (relative to the working directory " +
              fs::current_path().string() + ")");
  refused("-table", {{"landcover_classes", {{"forest", 3}}}}, inputs,
          "synthesis.transfer.landcover_classes: key 'forest' is not an integer");
  // The DEM mapped as the land cover: no height is in the table, every pixel would take any class.
  refused("-heights", json::object(), {{"landcover", "dem"}, {"dem", "dem"}},
          "(synthesis.transfer): inputs.landcover: layer 'dem' is continuous, but the port takes "
          "a categorical layer (target land-cover classes (ingest them with \"as\": "
          "\"landcover\"))");
}

TEST(TransferZion, ThePaintingsBlackIsAColourNotNodata) {
  if (!fs::exists(kShared + "/zion/nlcd.tif")) GTEST_SKIP() << "../shared/data is absent";
  // 64 x 64: black on the left half, yellow (255, 200, 0) on the right; both classes may paint
  // every land cover. The rgb layer's nodata is 0: a channel copied at 0 must not read as a hole.
  const std::string painting = maquette::test::write_png(
      maquette::test::temp_dir() + "/black.png", 64, 64, 3, [](int x, int, int b) {
        return x < 32 ? 0.0 : b == 0 ? 255.0 : b == 1 ? 200.0 : 0.0;
      });
  const json any = {0, 1};
  const TransferRun run =
      run_transfer("-black", 2, "",
                   {{"painting", painting},
                    {"classes", 2},
                    {"exemplar_scale", 1},
                    {"landcover_classes", {{"3", any}, {"4", any}, {"5", any}, {"6", any}}}});
  const auto store = Store::open(run.store, Store::Mode::ReadOnly);
  size_t black = 0, yellow = 0, zero = 0;
  for (const CellId cell : store->tile_cells("painted")) {
    const RawTile rgb = *store->get_tile("painted", cell);
    const Tile<float> source = to_tile<float>(*store->get_tile("painted_source", cell));
    for (int r = 0; r < source.size(); ++r)
      for (int c = 0; c < source.size(); ++c) {
        if (std::isnan(source.at(c, r, 0))) continue;
        const bool left = source.at(c, r, 0) < 32;
        (left ? black : yellow) += 1;
        for (int k = 0; k < 3; ++k) {
          const int got = std::to_integer<int>(
              rgb.bytes[(size_t(r) * size_t(rgb.size) + size_t(c)) * 3 + size_t(k)]);
          zero += got == 0;
          EXPECT_EQ(got, left ? 1 : k == 0 ? 255 : k == 1 ? 200 : 1) << cell.ToText();
        }
      }
  }
  EXPECT_GT(black, 1000u);
  EXPECT_GT(yellow, 1000u);
  EXPECT_EQ(zero, 0u);
  fs::remove_all(run.dir);
}

// synthesis.apply (apply_sources.h) after the transfer: applied to the painting itself, the
// transfer's colours byte for byte; applied to an image of the painting's columns, each pixel its
// source's block: the mean of its columns, or as classes (every column once, a tie) the first.
TEST(TransferZion, TheSourcesAppliedToThePaintingAreTheTransfersColours) {
  if (!fs::exists(kPainting) || !fs::exists(kShared + "/zion/nlcd.tif"))
    GTEST_SKIP() << "../shared/data is absent";
  int width = 0, height = 0;
  painting_rgb(width, height);
  test::RasterSpec spec;
  spec.width = width;
  spec.height = height;
  spec.geotransform = {0, 1, 0, 0, 0, 1};  // pixel centres at (x + 0.5, y + 0.5)
  const std::string columns = test::temp_dir() + "/painting-columns.tif";
  test::write_raster(columns, spec, [](int, double x, double) { return std::floor(x); });
  const auto apply = [](const std::string& output, const std::string& layer, const json& params) {
    return json{{"op", "synthesis.apply"},
                {"inputs", {{"source", "painted_source"}}},
                {"outputs", {{output, layer}}},
                {"params", params}};
  };
  const json then = json::array(
      {apply("rgb", "applied", {{"images", {kPainting}}}),
       apply("value", "column_mean", {{"images", {columns}}}),
       apply("classes", "column_mode", {{"images", {columns}}, {"exemplar_scale", kScale}})});
  const TransferRun run = run_transfer("-apply", 2, "", json::object(), nullptr,
                                       {{"landcover", "landcover"}, {"dem", "dem"}}, then);
  const auto store = Store::open(run.store, Store::Mode::ReadOnly);
  const std::vector<CellId> cells = store->tile_cells("painted");
  ASSERT_GE(cells.size(), 2u);
  size_t sources = 0, wrong_mean = 0, wrong_mode = 0, missing = 0;
  for (const CellId cell : cells) {
    EXPECT_EQ(store->get_tile("applied", cell)->bytes, store->get_tile("painted", cell)->bytes)
        << cell.ToText();
    const Tile<float> source = to_tile<float>(*store->get_tile("painted_source", cell));
    const Tile<float> mean = to_tile<float>(*store->get_tile("column_mean", cell));
    const Tile<float> mode = to_tile<float>(*store->get_tile("column_mode", cell));
    for (int r = 0; r < source.size(); ++r)
      for (int c = 0; c < source.size(); ++c) {
        const float col = source.at(c, r, 0);
        if (std::isnan(col)) {
          missing += !std::isnan(mean.at(c, r)) + !std::isnan(mode.at(c, r));
          continue;
        }
        ++sources;
        wrong_mean += mean.at(c, r) != col + (kScale - 1) / 2.0f;
        wrong_mode += mode.at(c, r) != col;
      }
  }
  EXPECT_GT(sources, 50000u);
  EXPECT_EQ(wrong_mean, 0u);
  EXPECT_EQ(wrong_mode, 0u);
  EXPECT_EQ(missing, 0u);
  fs::remove_all(run.dir);

  // Refused by name: another exemplar_scale than the transfer's, two images for its one painting,
  // a missing image, values that are no classes mapped to classes.
  const auto refused = [&](const std::string& name, const json& params, const std::string& message,
                           const std::string& output = "rgb") {
    test::CliResult r;
    const TransferRun bad =
        run_transfer(name, 2, "", json::object(), &r, {{"landcover", "landcover"}, {"dem", "dem"}},
                     json::array({apply(output, "applied", params)}));
    EXPECT_NE(r.exit_code, 0) << name;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    fs::remove_all(bad.dir);
  };
  refused("-apply-scale", {{"images", {kPainting}}, {"exemplar_scale", 2}},
          "synthesis.apply.exemplar_scale 2: the source layer 'painted_source' was made by "
          "synthesis.transfer at exemplar_scale 4: give 4 or leave exemplar_scale out");
  refused("-apply-images", {{"images", {kPainting, kPainting}}},
          "synthesis.apply.images: 2 for the 1 painting(s) of the synthesis.transfer that made "
          "'painted_source'");
  refused("-apply-missing", {{"images", {"no/such.png"}}}, "no/such.png");
  const std::string halves = test::temp_dir() + "/painting-halves.tif";
  test::write_raster(halves, spec, [](int, double x, double) { return x; });  // centres: n + 0.5
  refused("-apply-halves", {{"images", {halves}}},
          ".500000, not a class (a whole number 0 .. 65534): map such an image to value",
          "classes");
  fs::remove(columns);
  fs::remove(halves);
}

}  // namespace
}  // namespace maquette::synthesis
