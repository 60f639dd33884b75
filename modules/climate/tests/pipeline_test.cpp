// The four operators in one pipeline through the runner: same bits with 1 and 2 threads.
#include "runtime/pipeline.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>

#include "climate_module.h"
#include "runtime/runner.h"

namespace maquette::climate {
namespace {

namespace fs = std::filesystem;
using climate_test::sample;

constexpr int kSize = 64;

// A store with a 2 x 2 block of DEM tiles (a ridge) and synthetic stations.
std::vector<CellId> make_store(const std::string& path) {
  const auto store = Store::open(path, Store::Mode::Create);
  LayerInfo dem;
  dem.name = "dem";
  dem.tile_size = kSize;
  dem.level = 8;
  dem.units = "m";
  store->create_layer(dem);
  std::vector<CellId> cells;
  for (uint32_t r = 0; r < 2; ++r)
    for (uint32_t c = 0; c < 2; ++c) cells.push_back(CellId::FromFaceColRow(1, 8, 100 + c, 60 + r));
  const LonLat origin = default_grid().centre(cells[3]);
  for (CellId cell : cells)
    store->put_tile("dem", cell,
                    from_tile(sample(cell, kSize,
                                     [&](LonLat p) {
                                       const double x = (p.lon - origin.lon) * 40;
                                       return 500 + 1500 * std::exp(-x * x) + 50 * p.lat;
                                     }),
                              DType::F32));
  json stations = json::array();
  for (int i = 0; i < 12; ++i) {
    const double z = 200 + 190 * i;
    stations.push_back(
        {{"id", std::to_string(i)},
         {"lon", origin.lon + 0.01 * i},
         {"lat", origin.lat + 0.005 * (i % 5)},
         {"elevation", z},
         {"values", {{"t", 25 - 6.5 * z / 1000 + 0.1 * (i % 3)}, {"p", 400 + 300 * z / 1000}}}});
  }
  const std::string text = json{{"columns", {"t", "p"}}, {"stations", stations}}.dump();
  store->put_artifact(Artifact::FromText("stations", text));
  return cells;
}

TEST(ClimatePipeline, SameBitsAnyThreadCount) {
  const fs::path dir =
      fs::temp_directory_path() / ("climate_pipeline_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::map<std::string, std::vector<std::byte>> first;
  for (const int threads : {1, 2}) {
    const std::string path = (dir / ("t" + std::to_string(threads) + ".mqt")).string();
    const std::vector<CellId> cells = make_store(path);
    json region = json::array();
    for (CellId c : cells) region.push_back(c.ToText());
    const json doc = {
        {"store", path},
        {"region", {{"cells", region}}},
        {"level", 8},
        {"tile_size", kSize},
        {"steps",
         {{{"op", "climate.fit_stations"},
           {"outputs", {{"fit", "fit"}}},
           {"params", {{"stations", "stations"}, {"columns", {"t", "p"}}}}},
          {{"op", "climate.regionalize"},
           {"inputs", {{"dem", "dem"}}},
           {"outputs", {{"temperature", "t"}, {"precipitation", "p0"}}},
           {"params",
            {{"fit", "fit"}, {"temperature_column", "t"}, {"precipitation_column", "p"}}}},
          {{"op", "climate.orographic"},
           {"inputs", {{"dem", "dem"}, {"precipitation", "p0"}}},
           {"outputs", {{"precipitation", "p"}}}},
          {{"op", "climate.solar"},
           {"inputs", {{"dem", "dem"}}},
           {"outputs", {{"radiation", "sun"}}},
           {"params", {{"day_step", 30}, {"minutes", 60}}}}}}};
    const Pipeline pipeline =
        parse_pipeline(doc.dump(), "test", dir.string(), climate_test::climate_registry());
    RunOptions options;
    options.threads = threads;
    options.quiet = true;
    run_pipeline(pipeline, options);
    const auto store = Store::open(path, Store::Mode::ReadOnly);
    std::map<std::string, std::vector<std::byte>> got;
    got["fit"] = store->get_artifact("fit")->data;
    for (const char* layer : {"t", "p0", "p", "sun"})
      for (CellId c : cells) {
        const auto tile = store->get_tile(layer, c);
        ASSERT_TRUE(tile) << layer;
        got[std::string(layer) + c.ToText()] = tile->bytes;
      }
    if (threads == 1)
      first = got;
    else
      EXPECT_TRUE(got == first);
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace maquette::climate
