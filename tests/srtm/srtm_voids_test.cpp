// terrain.fill_voids on the SRTM Everest tile (../shared/data/srtm3, 9 % voids of -32768, some
// of them hundreds of pixels long) through the real program: ingest, a pipeline filling the
// voids from the layer's overview pyramid, and a picture. Every sample of the voids enclosed by
// data is filled (voids open to the tile's edge, where the store cannot tell a void from the
// outside of the data, are filled only where data enclose them); neighbouring filled samples
// differ across tile edges as elsewhere (no seams); the fill is the same bits with 1 and 2
// threads (tilings: modules/terrain/tests/fill_large_voids_test.cpp). Skipped when the data is
// absent.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "core/grid.h"
#include "core/halo.h"
#include "run_cli.h"
#include "store/store.h"

namespace maquette::test {
namespace {

const std::string kEverest = std::string(MAQUETTE_SHARED_DIR) + "/data/srtm3/mt_everest_90m.tif";
// The tile's footprint (its pixels' outer edges), shrunk by half a source pixel.
constexpr double kWest = 85.99958 + 0.0004, kEast = 87.00042 - 0.0004, kSouth = 26.99958 + 0.0004,
                 kNorth = 28.00042 - 0.0004;

using Samples = std::map<std::pair<int64_t, int64_t>, float>;  // by global pixel of the face

// Every sample of `layer` by global face pixel (Everest's tiles are all on face Q).
Samples samples(const Store& store, const std::string& layer) {
  const LayerInfo info = store.require_layer(layer);
  const double* nodata = info.nodata ? &*info.nodata : nullptr;
  Samples out;
  for (const CellId cell : store.tile_cells(layer)) {
    const Tile<float> tile = to_tile<float>(*store.get_tile(layer, cell), nodata);
    for (int r = 0; r < tile.size(); ++r)
      for (int c = 0; c < tile.size(); ++c)
        out[{global_col(cell, tile.size(), c), global_row(cell, tile.size(), r)}] = tile.at(c, r);
  }
  return out;
}

// Ingests the Everest tile with `tile_size` and fills it with `threads` threads; the store.
std::string ingest_and_fill(const std::string& dir, int tile_size, int threads) {
  const std::string store = dir + "/everest.mqt";
  const CliResult ingest =
      run_maquette("--quiet ingest " + store + " " + kEverest +
                   " --layer voids --as dem --tile-size " + std::to_string(tile_size));
  EXPECT_EQ(ingest.exit_code, 0) << ingest.err;
  const nlohmann::json pipeline = {{"store", store},
                                   {"region", {{"bbox", {85.9, 26.9, 87.1, 28.1}}}},
                                   {"level", 0},
                                   {"steps",
                                    {{{"op", "terrain.fill_voids"},
                                      {"inputs", {{"dem", "voids"}}},
                                      {"outputs", {{"dem", "filled"}, {"filled", "mask"}}},
                                      {"params", {{"pyramid", "voids"}}}}}}};
  std::ofstream(dir + "/fill.json") << pipeline.dump();
  const CliResult run =
      run_maquette("--quiet run " + dir + "/fill.json --threads " + std::to_string(threads));
  EXPECT_EQ(run.exit_code, 0) << run.err;
  return store;
}

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(SrtmVoids, EverestVoidsAreAllFilled) {
  if (!std::filesystem::exists(kEverest)) GTEST_SKIP() << "no " << kEverest;
  const std::string dir = temp_dir();
  const std::string path = ingest_and_fill(dir, 256, 2);
  const std::unique_ptr<Store> store = Store::open(path, Store::Mode::ReadOnly);
  const Samples voids = samples(*store, "voids"), filled = samples(*store, "filled");
  ASSERT_EQ(voids.size(), filled.size());
  const int level = store->require_layer("voids").level + 8;
  const int face = store->tile_cells("voids").front().face();
  const auto inside = [&](std::pair<int64_t, int64_t> xy) {
    const LonLat p = pixel_centre(default_grid(), FaceCoord{face, xy.first, xy.second}, level);
    return p.lon > kWest && p.lon < kEast && p.lat > kSouth && p.lat < kNorth;
  };
  // The voids (4-connected) inside the tile's footprint, each open (next to a sample outside
  // the footprint, where no data can enclose it) or enclosed by data.
  std::map<std::pair<int64_t, int64_t>, bool> open;  // void sample -> its void is open
  int64_t samples_inside = 0;
  for (const auto& [xy, v] : voids) {
    if (!inside(xy)) continue;
    ++samples_inside;
    const float f = filled.at(xy);
    if (!std::isnan(v)) {
      ASSERT_TRUE(same_bits(f, v)) << xy.first << "," << xy.second;
      continue;
    }
    if (open.count(xy)) continue;
    std::vector<std::pair<int64_t, int64_t>> component{xy}, stack{xy};
    bool is_open = false;
    open[xy] = false;
    while (!stack.empty()) {
      const auto [x, y] = stack.back();
      stack.pop_back();
      for (const auto& n :
           {std::pair{x - 1, y}, std::pair{x + 1, y}, std::pair{x, y - 1}, std::pair{x, y + 1}}) {
        const auto it = voids.find(n);
        if (it == voids.end() || !inside(n)) {
          is_open = true;
        } else if (std::isnan(it->second) && !open.count(n)) {
          open[n] = false;
          component.push_back(n);
          stack.push_back(n);
        }
      }
    }
    for (const auto& s : component) open[s] = is_open;
  }
  int64_t enclosed = 0, enclosed_holes = 0, open_samples = 0, open_holes = 0;
  for (const auto& [xy, is_open] : open) {
    const float f = filled.at(xy);
    (is_open ? open_samples : enclosed) += 1;
    if (std::isnan(f)) {
      (is_open ? open_holes : enclosed_holes) += 1;
    } else {
      // Within the tile's known heights (192..8642 m): a membrane keeps to its border's range.
      ASSERT_TRUE(f > 192 && f < 8642) << f << " at " << xy.first << "," << xy.second;
    }
  }
  std::cout << samples_inside << " samples inside the tile, " << enclosed << " in enclosed voids ("
            << enclosed_holes << " left), " << open_samples << " in voids open to the tile's edge ("
            << open_holes << " left)\n";
  RecordProperty("open_void_samples_left", std::to_string(open_holes));
  EXPECT_GT(double(enclosed) / double(samples_inside), 0.04);
  EXPECT_EQ(enclosed_holes, 0);

  // No seams: neighbouring filled samples differ across tile edges as they do elsewhere.
  double across = 0, elsewhere = 0;
  int64_t n_across = 0, n_elsewhere = 0;
  for (const auto& [xy, v] : voids) {
    for (const auto& n : {std::pair{xy.first + 1, xy.second}, std::pair{xy.first, xy.second + 1}}) {
      const auto it = voids.find(n);
      if (!std::isnan(v) || it == voids.end() || !std::isnan(it->second)) continue;
      const float a = filled.at(xy), b = filled.at(n);
      if (std::isnan(a) || std::isnan(b)) continue;
      const bool edge = n.first != xy.first ? n.first % 256 == 0 : n.second % 256 == 0;
      (edge ? across : elsewhere) += std::abs(a - b);
      ++(edge ? n_across : n_elsewhere);
    }
  }
  const double ratio = (across / double(n_across)) / (elsewhere / double(n_elsewhere));
  std::cout << "filled neighbours differ by " << across / double(n_across) << " m across "
            << n_across << " tile edges, " << elsewhere / double(n_elsewhere) << " m elsewhere\n";
  EXPECT_GT(n_across, 500);
  EXPECT_LT(ratio, 1.5);

  const CliResult png = run_maquette("--quiet export png " + path + " " + dir +
                                     "/filled.png --layer filled --hillshade");
  EXPECT_EQ(png.exit_code, 0) << png.err;
  EXPECT_GT(std::filesystem::file_size(dir + "/filled.png"), 10000u);
}

TEST(SrtmVoids, SameBitsForAnyThreads) {
  if (!std::filesystem::exists(kEverest)) GTEST_SKIP() << "no " << kEverest;
  const std::string a = temp_dir(), b = temp_dir();
  const Samples one =
      samples(*Store::open(ingest_and_fill(a, 256, 1), Store::Mode::ReadOnly), "filled");
  const Samples two =
      samples(*Store::open(ingest_and_fill(b, 256, 2), Store::Mode::ReadOnly), "filled");
  ASSERT_EQ(one.size(), two.size());
  for (const auto& [xy, v] : one)
    ASSERT_TRUE(same_bits(v, two.at(xy))) << xy.first << "," << xy.second;
}

}  // namespace
}  // namespace maquette::test
