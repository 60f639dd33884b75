// The painted drape of examples/synthesis-zion.json: the example's ingest, synthesis.transfer and
// tiles3d export steps on a few of its cells (its sources in ../shared/data), through the real
// program. The export is read as a viewer reads it (tests/tiles3d/tileset_reader.h: the tiles'
// bounding regions, every content) and the Khronos glTF validator finds no error in its GLB (when
// installed). Each finest tile's texture, decoded by GDAL (a JPEG), is compared texel
// by texel with the store's `painted` tile of the same cell: it is the painted layer as stored
// (no display stretch): mean absolute difference at most kMaxJpegError per channel, JPEG's loss
// (6.0 and 6.9 measured; the layer one texel to the side is 12-13 from the texture, upside down
// 26-29), and at least kMinOtherError from the Landsat scene the example also ingests (54 and 66
// measured). Skipped when the data is absent.
#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/cell_id.h"
#include "example_pipeline.h"
#include "run_cli.h"
#include "store/store.h"
#include "stored_layers.h"
#include "tileset_reader.h"

namespace maquette::test {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

constexpr double kMaxJpegError = 9.0;    // mean |texel - layer| per channel, 0..255
constexpr double kMinOtherError = 30.0;  // the same from a layer the texture is not

// The example with the store and exports in `dir` on a 0.02 degree box east of Zion Canyon (a
// few level-10 cells), without its PNG and GeoTIFF exports; its painting (a path from the
// repository's root, where the README runs it) as an absolute path.
json example(const std::string& dir) {
  json p = example_pipeline("synthesis-zion");
  p["store"] = dir + "/synthesis-zion.mqt";
  p["region"] = {{"bbox", {-112.94, 37.24, -112.92, 37.26}}};
  json steps = json::array();
  for (json s : p["steps"]) {
    json& params = s["params"];
    if (s["op"] == "export" && params["format"] != "tiles3d") continue;
    if (params.contains("painting"))
      params["painting"] =
          std::string(MAQUETTE_SOURCE_DIR) + "/" + params["painting"].get<std::string>();
    if (s["op"] == "export") params["out"] = dir + "/tiles3d";
    steps.push_back(s);
  }
  p["steps"] = steps;
  return p;
}

// An image file's texels, band-interleaved by pixel (RGB), and its side; empty if it is not a
// square RGB image GDAL reads.
struct Rgb {
  int size = 0;
  std::vector<uint8_t> texels;
};
Rgb decode(const std::vector<char>& bytes) {
  GDALAllRegister();
  const std::string mem = "/vsimem/drape_texture";
  VSIFCloseL(VSIFileFromMemBuffer(mem.c_str(), (GByte*)bytes.data(), bytes.size(), FALSE));
  Rgb rgb;
  GDALDatasetUniquePtr ds(GDALDataset::Open(mem.c_str(), GDAL_OF_RASTER));
  if (ds && ds->GetRasterCount() == 3 && ds->GetRasterXSize() == ds->GetRasterYSize()) {
    rgb.size = ds->GetRasterXSize();
    rgb.texels.resize(size_t(3) * rgb.size * rgb.size);
    if (ds->RasterIO(GF_Read, 0, 0, rgb.size, rgb.size, rgb.texels.data(), rgb.size, rgb.size,
                     GDT_Byte, 3, nullptr, 3, 3 * rgb.size, 1) != CE_None)
      rgb = {};
  }
  ds.reset();
  VSIUnlink(mem.c_str());
  return rgb;
}

// The mean |texel - value| over the channels and texels of `tile` that hold data.
double mean_error(const Rgb& texture, const Tile<float>& tile) {
  double sum = 0;
  size_t n = 0;
  for (int row = 0; row < tile.size(); ++row)
    for (int col = 0; col < tile.size(); ++col)
      for (int c = 0; c < 3; ++c) {
        const float v = tile.at(col, row, c);
        if (std::isnan(v)) continue;
        sum += std::abs(texture.texels[3 * (size_t(row) * texture.size + col) + c] - v);
        ++n;
      }
  return n ? sum / double(n) : NAN;
}

TEST(SynthesisZionDrape, TexturesAreThePaintedLayer) {
  if (!fs::exists(kShared + "/data/zion/srtm.tif") || !fs::exists(kShared + "/data/painting"))
    GTEST_SKIP() << "../shared/data/zion or ../shared/data/painting is absent";
  const std::string dir = temp_dir() + "/synthesis_zion_drape";
  fs::create_directories(dir);
  const json pipeline = example(dir);
  std::ofstream(dir + "/pipeline.json") << pipeline.dump(1);
  const CliResult run = run_maquette("-q run " + dir + "/pipeline.json");
  ASSERT_EQ(run.exit_code, 0) << run.err;

  const Export tiles = read_export(dir + "/tiles3d");  // the tileset's checks
  if (const auto valid = gltf_validator_passes(dir + "/tiles3d")) {
    EXPECT_TRUE(*valid) << "the Khronos glTF validator finds errors";
  }
  const auto store = Store::open(dir + "/synthesis-zion.mqt", Store::Mode::ReadOnly);
  const std::string finest = "tiles/" + std::to_string(pipeline["level"].get<int>()) + "/";
  int compared = 0;
  for (const CellId cell : store->tile_cells("painted")) {
    const std::string name = finest + cell.ToText() + ".glb";
    ASSERT_TRUE(tiles.glbs.contains(name)) << name << " is not in the tileset";
    const Glb& glb = tiles.glbs.at(name);
    ASSERT_TRUE(glb.json.contains("images")) << name << " has no texture";
    const Tile<float> painted = float_tile(*store, "painted", cell);
    const Rgb texture = decode(glb.image(0));
    ASSERT_EQ(texture.size, painted.size()) << name << ": no RGB texture of the layer's size";
    const double error = mean_error(texture, painted);
    const double landsat = mean_error(texture, float_tile(*store, "landsat", cell));
    std::cout << name << ": mean |texture - painted| " << error << ", - landsat " << landsat
              << "\n";
    EXPECT_LE(error, kMaxJpegError) << name;
    EXPECT_GT(landsat, kMinOtherError) << name << ": the texture is the Landsat scene";
    ++compared;
  }
  EXPECT_GE(compared, 2);
}

}  // namespace
}  // namespace maquette::test
