// terrain.fill_voids on the SRTM tiles (../shared/data/srtm3) through the real program: ingest,
// a pipeline filling the voids from the layer's overview pyramid, and a picture. On Everest (9 %
// voids of -32768, some of them hundreds of pixels long) every sample of every void inside the
// tile's footprint (recorded at ingest) is filled, those open to the tile's edge too;
// neighbouring filled samples differ across tile edges as elsewhere (no seams); the
// fill is the same bits with 1 and 2 threads and with 256- and 512-pixel tiles. On Rainier, a
// void of 500 pixels that swallows whole 256-pixel tiles is filled, those tiles too, and a void
// along the tile's edge: both compared with GDAL's FillNodata (gdal_fillnodata.py, a separate
// process) against the heights removed. Skipped when the data is absent.
#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <vector>

#include "core/grid.h"
#include "core/halo.h"
#include "run_cli.h"
#include "store/store.h"
#include "stored_layers.h"

namespace maquette::test {
namespace {

const std::string kSrtm = std::string(MAQUETTE_SHARED_DIR) + "/data/srtm3/";
const std::string kEverest = kSrtm + "mt_everest_90m.tif", kRainier = kSrtm + "mt_rainier_90m.tif";

// A lon/lat box W S E N.
struct Box {
  double west, south, east, north;
  bool contains(LonLat p) const {
    return p.lon > west && p.lon < east && p.lat > south && p.lat < north;
  }
};
// The tiles' footprints (their pixels' outer edges: 1201 pixels of 3"), shrunk by half a source
// pixel.
constexpr double kShrink = 0.0004;
constexpr Box kEverestBox{85.99958 + kShrink, 26.99958 + kShrink, 87.00042 - kShrink,
                          28.00042 - kShrink};
constexpr Box kRainierBox{-122.00042 + kShrink, 45.99958 + kShrink, -120.99958 - kShrink,
                          47.00042 - kShrink};

using Samples = std::map<std::pair<int64_t, int64_t>, float>;  // by global pixel of the face

// Every sample of `layer` by global face pixel (Everest's tiles are all on face Q).
Samples samples(const Store& store, const std::string& layer) {
  Samples out;
  for (const CellId cell : store.tile_cells(layer)) {
    const Tile<float> tile = float_tile(store, layer, cell);
    for (int r = 0; r < tile.size(); ++r)
      for (int c = 0; c < tile.size(); ++c)
        out[{global_col(cell, tile.size(), c), global_row(cell, tile.size(), r)}] = tile.at(c, r);
  }
  return out;
}

// Ingests `source` as layer `layer` with `tile_size`.
void ingest(const std::string& store, const std::string& source, const std::string& layer,
            int tile_size) {
  const CliResult run = run_maquette("--quiet ingest " + store + " " + source + " --layer " +
                                     layer + " --as dem --tile-size " + std::to_string(tile_size));
  EXPECT_EQ(run.exit_code, 0) << run.err;
}

// Ingests the tile `source` (Everest by default) with `tile_size` and fills it with `threads`
// threads; the store.
// Fills layer `voids` of `store` into `filled` with `threads` threads; the store.
std::string fill(const std::string& store, int threads) {
  const std::string dir = std::filesystem::path(store).parent_path();
  const nlohmann::json pipeline = {{"store", store},
                                   {"region", {{"cells", {"N", "O", "P", "Q", "R", "S"}}}},
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

std::string ingest_and_fill(const std::string& dir, int tile_size, int threads,
                            const std::string& source = kEverest) {
  const std::string store = dir + "/srtm.mqt";
  ingest(store, source, "voids", tile_size);
  return fill(store, threads);
}

// A new store whose layer `voids` holds the samples of `store`'s in tiles of `tile_size` (a
// multiple of its own; same provenance, footprint included), with its overviews: the same input
// in another tiling (the ingest's resampling differs slightly between tilings).
std::string retiled(const std::string& store, int tile_size) {
  const std::unique_ptr<Store> from = Store::open(store, Store::Mode::ReadOnly);
  LayerInfo info = from->require_layer("voids");
  const int size = info.tile_size, up = log2_tile_size(tile_size / size);
  info.tile_size = tile_size;
  info.level -= up;
  const std::string path = temp_dir() + "/retiled.mqt";
  const std::unique_ptr<Store> to = Store::open(path, Store::Mode::Create);
  to->create_layer(info);
  std::map<CellId, Tile<float>> tiles;
  for (const CellId cell : from->tile_cells("voids")) {
    const CellId parent = cell.parent(info.level);
    auto it = tiles.try_emplace(parent, tile_size, 1, 0, NAN).first;
    const Tile<float> tile = to_tile<float>(*from->get_tile("voids", cell));
    for (int r = 0; r < size; ++r)
      for (int c = 0; c < size; ++c)
        it->second.at(int(global_col(cell, size, c) - global_col(parent, tile_size, 0)),
                      int(global_row(cell, size, r) - global_row(parent, tile_size, 0))) =
            tile.at(c, r);
  }
  for (const auto& [cell, tile] : tiles) to->put_tile("voids", cell, from_tile(tile, DType::F32));
  to->update_overviews("voids");
  return path;
}

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(SrtmVoids, EverestVoidsAreAllFilled) {
  if (!std::filesystem::exists(kEverest)) GTEST_SKIP() << "no " << kEverest;
  const std::string dir = temp_dir();
  const std::string path = ingest_and_fill(dir, 256, 2);
  const std::unique_ptr<Store> store = Store::open(path, Store::Mode::ReadOnly);
  const Samples voids = samples(*store, "voids"), filled = samples(*store, "filled");
  const int level = store->require_layer("voids").level + 8;
  const int face = store->tile_cells("voids").front().face();
  const auto inside = [&](std::pair<int64_t, int64_t> xy) {
    return kEverestBox.contains(
        pixel_centre(default_grid(), FaceCoord{face, xy.first, xy.second}, level));
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
  EXPECT_GT(double(enclosed) / double(samples_inside), 0.04);
  EXPECT_GT(double(open_samples) / double(enclosed + open_samples), 0.05);
  EXPECT_EQ(enclosed_holes, 0);
  EXPECT_EQ(open_holes, 0);

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

// 256-pixel tiles (the coarsest level of the pyramid is their faces' tile) and the same samples
// in 512-pixel ones (their faces' tile halved), 1 and 2 threads.
TEST(SrtmVoids, SameBitsForAnyTilingAndThreads) {
  if (!std::filesystem::exists(kEverest)) GTEST_SKIP() << "no " << kEverest;
  const std::string one_path = ingest_and_fill(temp_dir(), 256, 1);
  const Samples one = samples(*Store::open(one_path, Store::Mode::ReadOnly), "filled");
  const Samples two =
      samples(*Store::open(ingest_and_fill(temp_dir(), 256, 2), Store::Mode::ReadOnly), "filled");
  const Samples large =
      samples(*Store::open(fill(retiled(one_path, 512), 2), Store::Mode::ReadOnly), "filled");
  ASSERT_EQ(one.size(), two.size());
  int64_t compared = 0;
  for (const auto& [xy, v] : one) {
    ASSERT_TRUE(same_bits(v, two.at(xy))) << xy.first << "," << xy.second;
    const auto it = large.find(xy);
    if (it == large.end()) continue;
    ASSERT_TRUE(std::isnan(v) ? std::isnan(it->second) : same_bits(v, it->second))
        << xy.first << "," << xy.second;
    ++compared;
  }
  EXPECT_GT(compared, 1201 * 1201);
}

// The Rainier tile with voids punched into it (-32768, GDAL): a square of 500 pixels at its
// centre and a strip of 150 x 300 pixels along its west edge, in 256-pixel tiles. The ingest
// writes no tile inside the square, and the fill writes those too (tiles of no input within the
// footprint); every sample inside the footprint is filled; the square closer to the heights
// removed than by GDAL's FillNodata, the edge strip as close.
TEST(SrtmVoids, WholeTileVoidsAreFilled) {
  if (!std::filesystem::exists(kRainier)) GTEST_SKIP() << "no " << kRainier;
  constexpr int kVoid = 500, kFirst = (1201 - kVoid) / 2, kEdgeVoid = 150;
  const std::string dir = temp_dir(), punched = dir + "/punched.tif";
  {
    GDALAllRegister();
    const std::unique_ptr<GDALDataset> src(GDALDataset::Open(kRainier.c_str(), GDAL_OF_RASTER));
    ASSERT_TRUE(src);
    std::unique_ptr<GDALDataset> out(GetGDALDriverManager()->GetDriverByName("GTiff")->CreateCopy(
        punched.c_str(), src.get(), false, nullptr, nullptr, nullptr));
    ASSERT_TRUE(out);
    std::vector<int16_t> nodata(size_t(kVoid) * kVoid, -32768);
    ASSERT_EQ(out->GetRasterBand(1)->RasterIO(GF_Write, kFirst, kFirst, kVoid, kVoid, nodata.data(),
                                              kVoid, kVoid, GDT_Int16, 0, 0),
              CE_None);
    ASSERT_EQ(
        out->GetRasterBand(1)->RasterIO(GF_Write, 0, 100, kEdgeVoid, 2 * kEdgeVoid, nodata.data(),
                                        kEdgeVoid, 2 * kEdgeVoid, GDT_Int16, 0, 0),
        CE_None);
  }
  const std::string path = ingest_and_fill(dir, 256, 2, punched);
  ingest(path, kRainier, "truth", 256);
  shell_output("gdal_fillnodata.py -q -md 2000 " + punched + " " + dir + "/gdal.tif");
  ingest(path, dir + "/gdal.tif", "gdal", 256);
  const std::unique_ptr<Store> store = Store::open(path, Store::Mode::ReadOnly);
  const size_t input_tiles = store->tile_cells("voids").size();
  const size_t output_tiles = store->tile_cells("filled").size();
  const Samples voids = samples(*store, "voids"), filled = samples(*store, "filled"),
                truth = samples(*store, "truth"), gdal = samples(*store, "gdal");
  const int level = store->require_layer("voids").level + 8;
  const int face = store->tile_cells("voids").front().face();
  int64_t void_samples = 0, holes = 0;
  struct Errors {
    int64_t count = 0;
    double ours = 0, gdal = 0;  // sums of squares
    double rmse(double sum) const { return std::sqrt(sum / double(count)); }
  } centre, edge;
  for (const auto& [xy, t] : truth) {
    const LonLat p = pixel_centre(default_grid(), FaceCoord{face, xy.first, xy.second}, level);
    const auto v = voids.find(xy);
    if (!kRainierBox.contains(p) || (v != voids.end() && !std::isnan(v->second))) continue;
    ++void_samples;
    const auto f = filled.find(xy);
    if (f == filled.end() || std::isnan(f->second)) {
      ++holes;
      continue;
    }
    if (std::isnan(t)) continue;  // a void of the source: no height to compare with
    Errors& e = p.lon < -121.8 ? edge : centre;
    const float g = gdal.at(xy);
    ++e.count;
    e.ours += (f->second - t) * (f->second - t);
    e.gdal += (g - t) * (g - t);
  }
  std::cout << input_tiles << " input tiles, " << output_tiles << " filled; " << void_samples
            << " void samples inside the footprint, " << holes << " left; RMSE against the "
            << "heights removed: centre " << centre.rmse(centre.ours) << " m (gdal_fillnodata "
            << centre.rmse(centre.gdal) << " m), west edge " << edge.rmse(edge.ours)
            << " m (gdal_fillnodata " << edge.rmse(edge.gdal) << " m)\n";
  RecordProperty("centre_rmse_m", std::to_string(centre.rmse(centre.ours)));
  RecordProperty("edge_rmse_m", std::to_string(edge.rmse(edge.ours)));
  EXPECT_GT(output_tiles, input_tiles);
  EXPECT_GT(centre.count, int64_t(kVoid) * kVoid);
  EXPECT_GT(edge.count, int64_t(kEdgeVoid) * kEdgeVoid);
  EXPECT_EQ(holes, 0);
  EXPECT_LT(centre.rmse(centre.ours), centre.rmse(centre.gdal));
  // Along the edge GDAL's inverse-distance weighting and the membrane with a free border there
  // do equally well (278.2 m and 277.5 m).
  EXPECT_LT(edge.rmse(edge.ours), 1.05 * edge.rmse(edge.gdal));
}

}  // namespace
}  // namespace maquette::test
