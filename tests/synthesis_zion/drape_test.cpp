// The painted drape of examples/synthesis-zion.json: the example's ingest, synthesis.transfer and
// tiles3d export steps on a few of its cells (its sources in ../shared/data), through the real
// program. Each finest tile's texture in the export, decoded by GDAL (a JPEG), is compared texel
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
#include <sstream>
#include <string>
#include <vector>

#include "core/cell_id.h"
#include "run_cli.h"
#include "store/store.h"
#include "stored_layers.h"

namespace maquette::test {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

const std::string kShared = std::string(MAQUETTE_SHARED_DIR) + "/data";
constexpr double kMaxJpegError = 9.0;    // mean |texel - layer| per channel, 0..255
constexpr double kMinOtherError = 30.0;  // the same from a layer the texture is not

// The example with the store and exports in `dir`, its sources in kShared, on a 0.02 degree box
// east of Zion Canyon (a few level-10 cells), without its PNG and GeoTIFF exports.
json example(const std::string& dir) {
  std::ifstream in(std::string(MAQUETTE_SOURCE_DIR) + "/examples/synthesis-zion.json");
  json p = json::parse(in);
  p["store"] = dir + "/synthesis-zion.mqt";
  p["region"] = {{"bbox", {-112.94, 37.24, -112.92, 37.26}}};
  json steps = json::array();
  for (json s : p["steps"]) {
    json& params = s["params"];
    if (s["op"] == "export" && params["format"] != "tiles3d") continue;
    if (s["op"] == "ingest")
      for (json& source : params["sources"])
        source = kShared + "/zion/" + fs::path(source.get<std::string>()).filename().string();
    if (params.contains("painting"))
      params["painting"] = kShared + "/painting/" +
                           fs::path(params["painting"].get<std::string>()).filename().string();
    if (s["op"] == "export") params["out"] = dir + "/tiles3d";
    steps.push_back(s);
  }
  p["steps"] = steps;
  return p;
}

// The bytes of image `index` of the GLB at `path` (its JSON chunk's bufferView into the BIN
// chunk); empty when the file or the image is missing.
std::string glb_image(const std::string& path, int index) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  const std::string glb = s.str();
  if (glb.size() < 20) return {};
  auto u32 = [&](size_t at) {
    uint32_t v = 0;
    glb.copy(reinterpret_cast<char*>(&v), 4, at);
    return size_t(v);
  };
  const size_t json_length = u32(12);
  const json doc = json::parse(glb.substr(20, json_length));
  if (!doc.contains("images")) return {};
  const json& view = doc["bufferViews"][doc["images"][index]["bufferView"].get<int>()];
  const size_t bin = 20 + json_length + 8;
  return glb.substr(bin + view.value("byteOffset", size_t(0)), view["byteLength"].get<size_t>());
}

// An image file's texels, band-interleaved by pixel (RGB), and its side; empty if it is not a
// square RGB image GDAL reads.
struct Rgb {
  int size = 0;
  std::vector<uint8_t> texels;
};
Rgb decode(const std::string& bytes) {
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
  if (!fs::exists(kShared + "/zion/srtm.tif") || !fs::exists(kShared + "/painting"))
    GTEST_SKIP() << "../shared/data/zion or ../shared/data/painting is absent";
  const std::string dir = temp_dir() + "/synthesis_zion_drape";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const json pipeline = example(dir);
  std::ofstream(dir + "/pipeline.json") << pipeline.dump(1);
  const CliResult run = run_maquette("-q run " + dir + "/pipeline.json");
  ASSERT_EQ(run.exit_code, 0) << run.err;

  const auto store = Store::open(dir + "/synthesis-zion.mqt", Store::Mode::ReadOnly);
  const std::string finest = dir + "/tiles3d/tiles/" + std::to_string(pipeline["level"].get<int>());
  int compared = 0;
  for (const CellId cell : store->tile_cells("painted")) {
    const std::string name = cell.ToText() + ".glb";
    const Tile<float> painted = float_tile(*store, "painted", cell);
    const Rgb texture = decode(glb_image(finest + "/" + name, 0));
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
