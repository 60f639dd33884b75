// A step's "refine" through the runner and the real texture module: texture.procedural writing
// tiles two levels finer than its DEM matches render_tile called directly on the DEM tiles, with
// the same bits for 1 and 2 threads; a tile size above the largest is refused before running.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/halo.h"
#include "field.h"   // modules/texture
#include "model.h"   // modules/texture
#include "render.h"  // modules/texture
#include "runtime/runner.h"
#include "store/store.h"
#include "test_util.h"

namespace maquette {
namespace {

using nlohmann::json;

const json kModel = json::parse(R"({
  "format": "maquette.texture.model", "version": 1,
  "quantities": [{"name": "height", "range": [0, 3000]}, {"name": "slope", "range": [0, 90]}],
  "root": {"colour": [150, 110, 90], "class": 0, "roughness_m": 3,
           "noise": {"seed": 3, "wavelength_m": 400}, "children": [
    {"class": 1, "colour": [80, 140, 60], "bias": 1, "noise_scale": 0.4,
     "noise": {"seed": 5, "wavelength_m": 600, "octaves": 4},
     "constraints": {"height": {"hat": [0, 100, 900, 1400]}}},
    {"class": 2, "colour": [240, 240, 245], "bias": 1,
     "constraints": {"height": {"hat": [900, 1400, 3000, 3100]}}}]}})");

const OperatorRegistry& registry() {
  static const OperatorRegistry r = OperatorRegistry::load({MAQUETTE_MODULE_DIR});
  return r;
}

// A synthetic DEM of 16 cells (16-pixel tiles) and its texture 2 levels finer (64-pixel tiles).
json refine_pipeline(int refine) {
  return {
      {"store", "out.mqt"},
      {"region", {{"cells", {"Q200"}}}},
      {"level", 5},
      {"tile_size", 16},
      {"steps",
       {{{"op", "terrain.synthesize"}, {"outputs", {{"dem", "dem"}}}, {"params", {{"seed", 7}}}},
        {{"op", "texture.procedural"},
         {"inputs", {{"dem", "dem"}}},
         {"outputs", {{"imagery", "texture"}, {"height", "height"}}},
         {"refine", refine},
         {"params", {{"model", kModel}}}}}}};
}

std::string run_in(const test::TempDir& dir, const json& doc, int threads) {
  RunOptions options;
  options.threads = threads;
  options.quiet = true;
  run_pipeline(load_pipeline(test::write_pipeline(dir, doc), registry()), options);
  return dir.file("out.mqt");
}

TEST(Refine, ProceduralTilesMatchRenderTileTwoLevelsFiner) {
  test::TempDir dir;
  const auto store = Store::open(run_in(dir, refine_pipeline(2), 2), Store::Mode::ReadOnly);
  const LayerInfo dem = store->require_layer("dem"), texture = store->require_layer("texture");
  EXPECT_EQ(texture.level, dem.level);  // the same cells, tiles of 16 << 2 samples
  EXPECT_EQ(texture.tile_size, 64);
  EXPECT_EQ(store->require_layer("height").tile_size, 64);
  const std::vector<CellId> cells = store->tile_cells("texture");
  ASSERT_EQ(cells.size(), 16u);

  const texture::Model model = texture::parse_model(kModel, "test");
  const double* no_nodata = nullptr;
  int64_t coloured = 0;  // samples with a colour (not nodata)
  for (const CellId cell : cells) {
    const Tile<float> dem_tile = assemble_halo(
        default_grid(), cell, 16, texture::kInputHalo, [&](CellId c) -> std::optional<Tile<float>> {
          const auto raw = store->get_tile("dem", c);
          if (!raw) return std::nullopt;
          return to_tile<float>(*raw, dem.nodata ? &*dem.nodata : no_nodata);
        });
    const texture::Rendered r =
        texture::render_tile(model, default_grid(), cell, 16, 2, dem_tile, {}, "test");
    ASSERT_EQ(r.size, 64);
    Tile<float> rgb(64, 3);
    std::copy(r.rgb.begin(), r.rgb.end(), rgb.data().begin());
    const double zero = 0;
    const Tile<uint8_t> expected = to_tile<uint8_t>(from_tile(rgb, DType::U8, &zero));
    const Tile<uint8_t> stored = to_tile<uint8_t>(*store->get_tile("texture", cell));
    ASSERT_EQ(stored.size(), 64);
    EXPECT_TRUE(std::equal(stored.data().begin(), stored.data().end(), expected.data().begin()))
        << cell.ToText();
    coloured +=
        std::count_if(stored.data().begin(), stored.data().end(), [](uint8_t v) { return v; });
    const Tile<float> height = to_tile<float>(*store->get_tile("height", cell));
    for (size_t i = 0; i < r.height.size(); ++i) {
      const float got = height.data()[i], want = r.height[i];  // NaN: no DEM in the halo
      ASSERT_TRUE(got == want || (std::isnan(got) && std::isnan(want)))
          << cell.ToText() << " sample " << i << ": " << got << " != " << want;
    }
  }
  EXPECT_GT(coloured, 16 * 64 * 64 * 3 / 2);
}

TEST(Refine, SameBitsWithOneAndTwoThreads) {
  test::TempDir one, two;
  const test::Snapshot a = test::snapshot(run_in(one, refine_pipeline(2), 1));
  const test::Snapshot b = test::snapshot(run_in(two, refine_pipeline(2), 2));
  EXPECT_FALSE(a.empty());
  EXPECT_EQ(test::first_difference(a, b), "");
}

TEST(Refine, TilesAboveTheLargestSizeAreRefusedBeforeRunning) {
  test::TempDir dir;
  EXPECT_EQ(
      test::error_of([&] { run_in(dir, refine_pipeline(9), 1); }),
      dir.file("pipeline.json") +
          ": step 2 (texture.procedural): refine: 9 levels finer than 16-sample tiles: tile size "
          "8192 is above the largest, 4096");
  EXPECT_FALSE(std::filesystem::exists(dir.file("out.mqt")));
}

}  // namespace
}  // namespace maquette
