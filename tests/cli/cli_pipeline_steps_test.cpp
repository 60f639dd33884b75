// The built-in `ingest` and `export` pipeline steps through the real program: a pipeline from a
// GeoTIFF to exported files (checked with GDAL against the source's known values and against the
// `maquette ingest` command), resume skipping a completed ingest, and bad params named.
#include <gdal.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "run_cli.h"
#include "store/store.h"
#include "synthetic_raster.h"

namespace maquette::test {
namespace {

using json = nlohmann::json;

// Linear in lon/lat, so that bilinear resampling (ingest, then export) reproduces it closely.
double ramp(int, double lon, double lat) { return 1000 * (lon + lat); }

class PipelineSteps : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = temp_dir();
    RasterSpec spec;
    spec.width = spec.height = 200;
    spec.geotransform = {10.0, 0.001, 0, 45.2, 0, -0.001};
    spec.crs = "EPSG:4326";
    write_raster(dir + "/dem.tif", spec, ramp);
  }

  // ingest dem.tif -> terrain.derive -> export gtiff (lon/lat) and png, into DIR/exports/.
  json pipeline() const {
    return {
        {"store", "out/p.mqt"},
        {"region", {{"bbox", {10.05, 45.05, 10.15, 45.15}}}},
        {"level", 9},
        {"steps",
         {{{"op", "ingest"},
           {"outputs", {{"layer", "dem"}}},
           {"params", {{"sources", {"dem.tif"}}, {"as", "dem"}, {"tile_size", 64}}}},
          {{"op", "terrain.derive"},
           {"inputs", {{"dem", "dem"}}},
           {"outputs", {{"slope", "slope"}}}},
          {{"op", "export"},
           {"params",
            {{"format", "gtiff"},
             {"layer", "dem"},
             {"crs", "EPSG:4326"},
             {"bbox", {10.05, 45.05, 10.15, 45.15}},
             {"out", "exports/dem.tif"}}}},
          {{"op", "export"},
           {"params", {{"format", "png"}, {"layer", "slope"}, {"out", "exports/slope.png"}}}}}}};
  }

  // `maquette run [run_options] DIR/pipeline.json`; logs on stderr unless run_options is "-q".
  CliResult run(const json& doc, const std::string& run_options = "-q") const {
    std::ofstream(dir + "/pipeline.json") << doc.dump(1);
    const bool quiet = run_options == "-q";
    return run_maquette(std::string(quiet ? "-q " : "") + "run " + (quiet ? "" : run_options) +
                        " " + dir + "/pipeline.json");
  }

  std::string dir;
};

TEST_F(PipelineSteps, IngestToExportedFiles) {
  const CliResult r = run(pipeline());
  ASSERT_EQ(r.exit_code, 0) << r.err;

  // The exported GeoTIFF, read with GDAL: lon/lat pixels holding the source's values.
  GDALAllRegister();
  const GDALDatasetH ds = GDALOpen((dir + "/exports/dem.tif").c_str(), GA_ReadOnly);
  ASSERT_NE(ds, nullptr);
  double gt[6];
  ASSERT_EQ(GDALGetGeoTransform(ds, gt), CE_None);
  const int w = GDALGetRasterXSize(ds), h = GDALGetRasterYSize(ds);
  EXPECT_GT(w, 50);
  EXPECT_GT(h, 50);
  std::vector<float> values(size_t(w) * size_t(h));
  ASSERT_EQ(GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Read, 0, 0, w, h, values.data(), w, h,
                         GDT_Float32, 0, 0),
            CE_None);
  GDALClose(ds);
  int checked = 0;
  double worst = 0;
  for (int y = 5; y < h - 5; ++y)
    for (int x = 5; x < w - 5; ++x) {
      const float v = values[size_t(y) * size_t(w) + size_t(x)];
      if (std::isnan(v)) continue;
      const double lon = gt[0] + (x + 0.5) * gt[1], lat = gt[3] + (y + 0.5) * gt[5];
      worst = std::max(worst, std::abs(v - ramp(1, lon, lat)));
      ++checked;
    }
  EXPECT_GT(checked, (w - 10) * (h - 10) / 2);
  EXPECT_LT(worst, 0.5) << "1000 (lon + lat) off by up to " << worst;

  const cv::Mat png = cv::imread(dir + "/exports/slope.png", cv::IMREAD_UNCHANGED);
  EXPECT_FALSE(png.empty());

  // The step ingests as the command does: the same tiles.
  const CliResult cmd = run_maquette("-q ingest " + dir + "/cmd.mqt --layer dem --as dem " +
                                     "--tile-size 64 " + dir + "/dem.tif");
  ASSERT_EQ(cmd.exit_code, 0) << cmd.err;
  const auto a = Store::open(dir + "/out/p.mqt", Store::Mode::ReadOnly);
  const auto b = Store::open(dir + "/cmd.mqt", Store::Mode::ReadOnly);
  EXPECT_EQ(a->require_layer("dem").level, b->require_layer("dem").level);
  const std::vector<CellId> cells = b->tile_cells("dem");
  EXPECT_EQ(a->tile_cells("dem"), cells);
  for (const CellId c : cells)
    ASSERT_EQ(a->get_tile("dem", c)->bytes, b->get_tile("dem", c)->bytes);
}

TEST_F(PipelineSteps, ResumeSkipsTheCompletedIngest) {
  json doc = pipeline();
  doc["steps"][3]["params"]["out"] = "pngs/slope.png";
  std::ofstream(dir + "/pngs") << "a file where the PNG's directory should be";
  const CliResult failed = run(doc);
  ASSERT_NE(failed.exit_code, 0);
  EXPECT_NE(failed.err.find("step 4 (export) failed: "), std::string::npos) << failed.err;
  const auto written = std::filesystem::last_write_time(dir + "/exports/dem.tif");
  std::filesystem::remove(dir + "/pngs");

  const CliResult resumed = run(doc, "--resume");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.err.find("step 1 (ingest): 29 cells (0 computed, 29 already done)"),
            std::string::npos)
      << resumed.err;
  EXPECT_NE(resumed.err.find("step 3 (export): 4 cells (0 computed, 4 already done)"),
            std::string::npos)
      << resumed.err;
  EXPECT_EQ(std::filesystem::last_write_time(dir + "/exports/dem.tif"), written);
  EXPECT_TRUE(std::filesystem::exists(dir + "/pngs/slope.png"));

  const CliResult again = run(doc, "");  // without --resume: everything again
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.err.find("step 1 (ingest): 29 cells (29 computed, 0 already done)"),
            std::string::npos)
      << again.err;
}

TEST_F(PipelineSteps, BadParamsNameTheStepFieldAndValue) {
  const std::string store = dir + "/out/p.mqt";
  auto error_with = [&](const std::function<void(json&)>& edit) {
    json doc = pipeline();
    edit(doc);
    const CliResult r = run(doc);
    EXPECT_NE(r.exit_code, 0);
    EXPECT_FALSE(std::filesystem::exists(store)) << "written before the error";
    return r.err;
  };
  auto contains = [](const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
  };
  std::string e = error_with([](json& d) { d["steps"][0]["params"]["as"] = "elevation"; });
  EXPECT_TRUE(contains(e, "step 1 (ingest): params.as: \"elevation\" is not one of")) << e;
  e = error_with([](json& d) { d["steps"][0]["params"]["sources"] = {"missing.tif"}; });
  EXPECT_TRUE(contains(e, "step 1 (ingest): ")) << e;
  EXPECT_TRUE(contains(e, "missing.tif")) << e;
  e = error_with([](json& d) { d["steps"][0]["params"]["bbox"] = {10, 95, 11, 96}; });
  EXPECT_TRUE(contains(e, "step 1 (ingest): params.bbox: latitude 95 is outside -90..90")) << e;
  e = error_with([](json& d) { d["steps"][2]["params"]["ramp"] = "grey"; });
  EXPECT_TRUE(contains(e,
                       "step 3 (export): params.ramp: not an option of format gtiff (it takes: "
                       "layer, bbox, cells, level, crs, resolution, max_mib, force)"))
      << e;
  e = error_with([](json& d) { d["steps"][3]["params"]["layer"] = "slop"; });
  EXPECT_TRUE(contains(e, "step 4 (export): params.layer: unknown layer 'slop' in " + store)) << e;
  e = error_with([](json& d) { d["steps"][3]["params"]["format"] = "jpeg"; });
  EXPECT_TRUE(contains(e, "step 4 (export): params.format: \"jpeg\" is not one of")) << e;
  e = error_with([](json& d) { d["steps"][3]["params"].erase("layer"); });
  EXPECT_TRUE(contains(e, "step 4 (export): params: format png needs \"layer\"")) << e;
}

}  // namespace
}  // namespace maquette::test
