// maquette-prism run as a user runs it (modules/structures/README.md "structures.prism").
#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "gltf/gltf_model.h"
#include "run_cli.h"

namespace maquette {
namespace {

namespace fs = std::filesystem;

struct ProgramRun {
  int exit_code = -1;
  std::string out;  // stdout and stderr
};

ProgramRun run_prism(const std::string& args) {
  const std::string command = std::string(MAQUETTE_BIN_DIR) + "/maquette-prism " + args + " 2>&1";
  ProgramRun r;
  FILE* pipe = popen(command.c_str(), "r");
  std::array<char, 4096> buffer;
  while (size_t n = fread(buffer.data(), 1, buffer.size(), pipe)) r.out.append(buffer.data(), n);
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

class PrismProgram : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(fs::path(MAQUETTE_SHARED_DIR) / "data/photos/building.jpg"))
      GTEST_SKIP() << "../shared/data/photos/building.jpg is absent";
    dir_ = fs::temp_directory_path() / ("maquette_prism_" + std::to_string(getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (!dir_.empty()) fs::remove_all(dir_);
  }
  fs::path dir_;
};

TEST_F(PrismProgram, ExampleGivesAModelTheIngestStores) {
  const std::string example = std::string(MAQUETTE_SOURCE_DIR) + "/examples/prism-building.json";
  const fs::path glb = dir_ / "building.glb", picture = dir_ / "building.png";
  const ProgramRun r = run_prism(example + " " + glb.string() + " --picture " + picture.string());
  ASSERT_EQ(r.exit_code, 0) << r.out;
  // The minimal clicks (three edges at the top-left corner, the far facade corners on their rays):
  // the extrusion behind the facade leaves one root of Eq. 9 in front of the camera.
  EXPECT_NE(r.out.find("(estimated), 1 roots of Eq. 9"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("exact (minimal clicks)"), std::string::npos) << r.out;
  // The model: metres, z up, its height the strokes' height_m; a slab as the photo shows it: the
  // facade (7 storeys, its panels about square once rectified) about twice as long as high,
  // the depth (drawn: hidden behind the cornice) shorter than the height.
  const MeshContent model = read_gltf_model(glb.string());
  std::array<float, 3> lo{1e30f, 1e30f, 1e30f}, hi{-1e30f, -1e30f, -1e30f};
  for (const MeshObject& o : model.objects)
    for (size_t i = 0; i < o.positions.size(); ++i)
      lo[i % 3] = std::min(lo[i % 3], o.positions[i]),
             hi[i % 3] = std::max(hi[i % 3], o.positions[i]);
  EXPECT_NEAR(lo[2], 0, 1e-3);
  EXPECT_NEAR(hi[2], 22, 1e-3);
  const float length = std::max(hi[0] - lo[0], hi[1] - lo[1]);
  const float depth = std::min(hi[0] - lo[0], hi[1] - lo[1]);
  EXPECT_GT(length / 22, 1.6);
  EXPECT_LT(length / 22, 2.4);
  EXPECT_GT(depth, 10);
  EXPECT_LT(depth, 22);
  const fs::path store = dir_ / "s.mqt";
  const test::CliResult ingest = test::run_maquette("ingest " + store.string() + " " +
                                                    glb.string() + " --layer hotel --as model");
  ASSERT_EQ(ingest.exit_code, 0) << ingest.err;
  const test::CliResult info = test::run_maquette("info " + store.string());
  EXPECT_NE(info.out.find("hotel: model"), std::string::npos) << info.out;
  // The picture: a PNG of 1000 x 700 with the model drawn on white.
  GDALAllRegister();
  std::unique_ptr<GDALDataset> png(GDALDataset::Open(picture.c_str(), GDAL_OF_RASTER));
  ASSERT_TRUE(png);
  EXPECT_EQ(png->GetRasterXSize(), 1000);
  EXPECT_EQ(png->GetRasterYSize(), 700);
  std::vector<uint8_t> band(1000 * 700);
  ASSERT_EQ(png->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, 1000, 700, band.data(), 1000, 700,
                                            GDT_Byte, 0, 0, nullptr),
            CE_None);
  const long drawn = std::count_if(band.begin(), band.end(), [](uint8_t v) { return v < 250; });
  EXPECT_GT(drawn, 1000 * 700 / 20);
}

TEST_F(PrismProgram, BadStrokesNamedAndNothingWritten) {
  const std::string photo = std::string(MAQUETTE_SHARED_DIR) + "/data/photos/building.jpg";
  const auto strokes = [&](const std::string& fields) {
    const fs::path path = dir_ / "strokes.json";
    std::ofstream(path) << "{\"photo\": \"" << photo << "\", " << fields << "}";
    return path.string();
  };
  const std::string good_profile = "\"profile\": [[526.7, 530.8], [526.7, 411.3], [564, 411.3]]";
  const struct {
    std::string fields, message;
  } cases[] = {
      {good_profile + ", \"corner\": 7, \"extrusion\": [512, 524]",
       "corner 7 is no profile vertex"},
      {"\"profile\": [[1, 2], \"x\"], \"corner\": 0, \"extrusion\": [512, 524]",
       "profile[1] is not a pixel"},
      {good_profile + ", \"corner\": 0", "field 'extrusion' is missing"},
      {good_profile + ", \"corner\": 0, \"extrusion\": [512, 524], \"height\": 3",
       "unknown field 'height'"},
      {good_profile + ", \"corner\": 0, \"extrusion\": [512, 524], \"focal_px\": -5",
       "field 'focal_px' is not a positive number: -5"},
  };
  const fs::path glb = dir_ / "none.glb";
  for (const auto& c : cases) {
    const std::string path = strokes(c.fields);
    const ProgramRun r = run_prism(path + " " + glb.string());
    EXPECT_EQ(r.exit_code, 1) << r.out;
    EXPECT_NE(r.out.find(path), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(c.message), std::string::npos) << r.out;
    EXPECT_FALSE(fs::exists(glb));
  }
}

}  // namespace
}  // namespace maquette
