// synthesis.inpaint run by the real program on Zion's Landsat imagery (../shared/data) with a
// bridge-like footprint crossing cells: the same tile bytes on one thread and two; every sample
// farther than the band from the footprint keeps the ingested bytes; the samples under it are
// filled (changed, none left nodata); a bridge removed end to end (structures.bridge's mask); a
// footprint that is no polygon is refused, naming it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "core/geo_distance.h"
#include "core/halo.h"
#include "core/polygon_set.h"
#include "core/tile.h"
#include "ring_feature.h"
#include "run_cli.h"
#include "store/store.h"
#include "zion_ingest.h"

namespace maquette::synthesis {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kLandsat = kShared + "/zion/landsat_rgb_b4b3b2_8bit.tif";

// A 6 km deck, 140 m wide, south-west to north-east across the region.
constexpr double kWest = -113.03, kEast = -112.98, kSouth = 37.255, kNorth = 37.295;
constexpr double kHalfWidth = 0.0007;  // degrees of latitude: ~78 m

std::string footprint(const std::string& type) {
  const json ring = {{kWest, kSouth - kHalfWidth},
                     {kEast, kNorth - kHalfWidth},
                     {kEast, kNorth + kHalfWidth},
                     {kWest, kSouth + kHalfWidth},
                     {kWest, kSouth - kHalfWidth}};
  return test::ring_feature(ring, type);
}

struct InpaintRun {
  fs::path dir;
  std::string store;
  test::CliResult result;
};

InpaintRun run_inpaint(const std::string& name, int threads, const std::string& type = "Polygon") {
  InpaintRun run{
      fs::temp_directory_path() / ("maquette-inpaint-" + std::to_string(getpid()) + name), "", {}};
  fs::remove_all(run.dir);
  fs::create_directories(run.dir);
  run.store = (run.dir / "zion.mqt").string();
  std::ofstream(run.dir / "bridge.geojson") << footprint(type);
  const json pipeline = {
      {"store", run.store},
      {"region", {{"bbox", {-113.03, 37.25, -112.98, 37.30}}}},
      {"level", 10},
      {"steps",
       {{{"op", "ingest"},
         {"outputs", {{"layer", "landsat"}}},
         {"params", {{"sources", {kLandsat}}, {"as", "imagery"}, {"level", 10}}}},
        {{"op", "ingest"},
         {"outputs", {{"layer", "bridge"}}},
         {"params", {{"sources", {(run.dir / "bridge.geojson").string()}}, {"as", "features"}}}},
        {{"op", "synthesis.inpaint"},
         {"inputs", {{"image", "landsat"}, {"footprints", "bridge"}}},
         {"outputs", {{"rgb", "filled"}}}}}}};
  std::ofstream(run.dir / "pipeline.json") << pipeline.dump(1);
  run.result = test::run_maquette("run " + (run.dir / "pipeline.json").string() +
                                  " --quiet --threads " + std::to_string(threads));
  return run;
}

TEST(InpaintOperator, FillsTheFootprintAcrossCellsKeepsTheRestSameBitsOnTwoThreads) {
  if (!fs::exists(kLandsat)) GTEST_SKIP() << "../shared/data is absent";
  const InpaintRun one = run_inpaint("-1", 1), two = run_inpaint("-2", 2);
  ASSERT_EQ(one.result.exit_code, 0) << one.result.err;
  ASSERT_EQ(two.result.exit_code, 0) << two.result.err;
  const auto a = Store::open(one.store, Store::Mode::ReadOnly);
  const auto b = Store::open(two.store, Store::Mode::ReadOnly);
  const std::vector<CellId> cells = a->tile_cells("filled");
  ASSERT_GE(cells.size(), 2u);
  const PolygonRings deck = {{{kWest, kSouth - kHalfWidth},
                              {kEast, kNorth - kHalfWidth},
                              {kEast, kNorth + kHalfWidth},
                              {kWest, kSouth + kHalfWidth},
                              {kWest, kSouth - kHalfWidth}}};
  Geometry deck_geometry;
  deck_geometry.type = GeometryType::Polygon;
  GeoPath outline;
  for (const LonLat& q : deck[0]) outline.push_back({q.lon, q.lat});
  deck_geometry.polygons.push_back({{outline}});
  size_t under = 0, changed_under = 0, nodata_under = 0, changed_far = 0, cells_with_deck = 0;
  for (const CellId cell : cells) {
    const RawTile filled = *a->get_tile("filled", cell);
    EXPECT_EQ(filled.bytes, b->get_tile("filled", cell)->bytes) << cell.ToText();
    const auto original = a->get_tile("landsat", cell);
    ASSERT_TRUE(original.has_value());
    const int n = filled.size, level = cell.level() + log2_tile_size(n);
    bool deck_here = false;
    for (int r = 0; r < n; ++r) {
      for (int c = 0; c < n; ++c) {
        const LonLat p = pixel_centre(
            default_grid(), {cell.face(), global_col(cell, n, c), global_row(cell, n, r)}, level);
        const size_t i = (size_t(r) * n + size_t(c)) * 3;
        bool differs = false, nodata = true;
        for (int k = 0; k < 3; ++k) {
          differs = differs || filled.bytes[i + k] != original->bytes[i + k];
          nodata = nodata && filled.bytes[i + k] == std::byte{0};
        }
        if (polygon_contains(deck, p)) {
          deck_here = true;
          ++under;
          changed_under += differs;
          nodata_under += nodata;
        } else if (differs) {
          // The band (3 samples of ~35 m) and rounding: nothing beyond 150 m of the deck.
          changed_far += distance_m(p, deck_geometry) > 150;
        }
      }
    }
    cells_with_deck += deck_here;
  }
  EXPECT_GE(cells_with_deck, 2u);
  EXPECT_GT(under, 300u);
  EXPECT_GE(double(changed_under), 0.9 * double(under));
  EXPECT_EQ(nodata_under, 0u);
  EXPECT_EQ(changed_far, 0u);
  fs::remove_all(one.dir);
  fs::remove_all(two.dir);
}

// Paper 002's Fig. 16 in the pipeline: a bridge's edge strokes -> structures.bridge (its deck and
// the footprint mask) -> synthesis.inpaint of the Landsat under the mask.
TEST(InpaintOperator, ABridgeRemovedEndToEnd) {
  if (!fs::exists(kLandsat)) GTEST_SKIP() << "../shared/data is absent";
  const fs::path dir =
      fs::temp_directory_path() / ("maquette-inpaint-bridge-" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string store = (dir / "zion.mqt").string();
  // Edges 2 km long, ~130 m apart.
  std::ofstream(dir / "strokes.geojson") << json{
      {"type", "FeatureCollection"},
      {"features",
       {{{"type", "Feature"},
         {"properties", {{"tool", "bridge"}}},
         {"geometry",
          {{"type", "MultiLineString"},
           {"coordinates",
            {{{-113.02, 37.27}, {-113.0, 37.28}}, {{-113.02, 37.2712}, {-113.0, 37.2812}}}}}}}}}};
  const json ingest_landsat = {
      {"op", "ingest"},
      {"outputs", {{"layer", "landsat"}}},
      {"params", {{"sources", {kLandsat}}, {"as", "imagery"}, {"level", 10}}}};
  json steps = zion_ingest_steps();
  steps.push_back(ingest_landsat);
  steps.push_back(
      {{"op", "ingest"},
       {"outputs", {{"layer", "strokes"}}},
       {"params", {{"sources", {(dir / "strokes.geojson").string()}}, {"as", "features"}}}});
  steps.push_back({{"op", "structures.bridge"},
                   {"inputs", {{"dem", "dem"}, {"strokes", "strokes"}}},
                   {"outputs", {{"mesh", "bridges"}, {"mask", "bridge_mask"}}}});
  steps.push_back({{"op", "synthesis.inpaint"},
                   {"inputs", {{"image", "landsat"}, {"mask", "bridge_mask"}}},
                   {"outputs", {{"rgb", "filled"}}}});
  const json pipeline = {{"store", store},
                         {"region", {{"bbox", {-113.03, 37.25, -112.98, 37.30}}}},
                         {"level", 10},
                         {"steps", steps}};
  std::ofstream(dir / "pipeline.json") << pipeline.dump(1);
  const test::CliResult r =
      test::run_maquette("run " + (dir / "pipeline.json").string() + " --quiet --threads 2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto s = Store::open(store, Store::Mode::ReadOnly);
  // The deck's samples by global face pixel, then every changed sample within the band of one.
  std::set<std::array<int64_t, 3>> deck;
  size_t under = 0, changed_under = 0, changed_beyond_band = 0;
  const auto cells = s->tile_cells("filled");
  for (const CellId cell : cells) {
    const Tile<float> mask = to_tile<float>(*s->get_tile("bridge_mask", cell));
    for (int row = 0; row < mask.size(); ++row) {
      for (int col = 0; col < mask.size(); ++col) {
        if (mask.at(col, row) == 1) {
          deck.insert({cell.face(), global_col(cell, mask.size(), col),
                       global_row(cell, mask.size(), row)});
        }
      }
    }
  }
  for (const CellId cell : cells) {
    const RawTile filled = *s->get_tile("filled", cell);
    const RawTile original = *s->get_tile("landsat", cell);
    const int n = filled.size;
    for (int row = 0; row < n; ++row) {
      for (int col = 0; col < n; ++col) {
        const size_t i = (size_t(row) * n + size_t(col)) * 3;
        const bool differs = filled.bytes[i] != original.bytes[i] ||
                             filled.bytes[i + 1] != original.bytes[i + 1] ||
                             filled.bytes[i + 2] != original.bytes[i + 2];
        const int64_t gc = global_col(cell, n, col), gr = global_row(cell, n, row);
        if (deck.count({cell.face(), gc, gr}) != 0) {
          ++under;
          changed_under += differs;
          continue;
        }
        if (!differs) continue;
        bool near = false;
        for (int dy = -3; dy <= 3 && !near; ++dy) {
          for (int dx = -3; dx <= 3 && !near; ++dx)
            near = deck.count({cell.face(), gc + dx, gr + dy}) != 0;
        }
        changed_beyond_band += !near;
      }
    }
  }
  EXPECT_GT(under, 100u);
  EXPECT_GE(double(changed_under), 0.9 * double(under));
  EXPECT_EQ(changed_beyond_band, 0u);
  fs::remove_all(dir);
}

TEST(InpaintOperator, AFootprintThatIsNoPolygonIsNamed) {
  if (!fs::exists(kLandsat)) GTEST_SKIP() << "../shared/data is absent";
  const InpaintRun run = run_inpaint("-line", 1, "LineString");
  EXPECT_NE(run.result.exit_code, 0);
  EXPECT_NE(run.result.err.find("inputs.footprints: feature 1 is a LineString, not a Polygon or "
                                "MultiPolygon"),
            std::string::npos)
      << run.result.err;
  fs::remove_all(run.dir);
}

}  // namespace
}  // namespace maquette::synthesis
