// export gtiff --crs EPSG:4326: nearest sampling checked pixel by pixel against the grid's own
// point-to-cell, bilinear against the smooth field the tiles sample, and both against gdalwarp
// run on our rHEALPix-plane export (ours samples the smooth field more closely: no widened kernel).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <sstream>

#include "export_fixture.h"
#include "run_cli.h"
#include "test_tiles.h"

namespace maquette::test {
namespace {

std::string export_to(const std::string& layer, const std::string& crs) {
  return export_layer("gtiff", layer, "tif", "--crs " + crs);
}

// Lon/lat of the centre of pixel (col, row) of a geographic raster.
LonLat pixel_centre(const double gt[6], int col, int row) {
  return {gt[0] + (col + 0.5) * gt[1], gt[3] + (row + 0.5) * gt[5]};
}

TEST(GtiffWarp, NearestPicksTheSampleOfTheCellHoldingEachPixelCentre) {
  const auto ds = open_raster(export_to("landcover", "EPSG:4326"));
  ASSERT_TRUE(ds);
  OGRSpatialReference wgs84;
  wgs84.importFromEPSG(4326);
  const char* const ignore_axis_order[] = {"IGNORE_DATA_AXIS_TO_SRS_AXIS_MAPPING=YES", nullptr};
  EXPECT_TRUE(ds->GetSpatialRef()->IsSame(&wgs84, ignore_axis_order));
  ASSERT_NE(ds->GetRasterBand(1)->GetColorTable(), nullptr);
  double gt[6];
  ASSERT_EQ(ds->GetGeoTransform(gt), CE_None);
  // Default resolution: the layer's pixel (~2.4 km) in degrees at the centre.
  EXPECT_NEAR(gt[1], 0.0219, 0.002);

  const auto& cells = export_fixture().dem_cells;
  const std::vector<double> v = read_band(*ds);
  const int w = ds->GetRasterXSize(), h = ds->GetRasterYSize();
  int data = 0, mismatches = 0;
  for (int row = 0; row < h; ++row)
    for (int col = 0; col < w; ++col) {
      const CellId pixel = default_grid().cell_from_point(pixel_centre(gt, col, row), kPixelLevel);
      const bool inside = std::count(cells.begin(), cells.end(), pixel.parent(kLevel)) > 0;
      const double expected = inside ? landcover_class(pixel.col(), pixel.row()) : 0.0;
      data += inside;
      mismatches += v[size_t(row) * w + col] != expected;
    }
  EXPECT_GT(data, 4 * kTileSize * kTileSize / 2);
  EXPECT_EQ(mismatches, 0);
}

TEST(GtiffWarp, BilinearFollowsTheSmoothField) {
  const auto ds = open_raster(export_to("dem", "EPSG:4326"));
  ASSERT_TRUE(ds);
  double gt[6];
  ASSERT_EQ(ds->GetGeoTransform(gt), CE_None);
  const std::vector<double> v = read_band(*ds);
  const int w = ds->GetRasterXSize(), h = ds->GetRasterYSize();
  // Pixels at least two layer pixels inside the tiles' plane square.
  const PlaneSquare a = default_grid().plane_square(export_fixture().dem_cells[0]);
  const double margin = 2 * a.side / kTileSize, x0 = a.x_min, y1 = a.y_max, side = 2 * a.side;
  double max_err = 0;
  int checked = 0;
  for (int row = 0; row < h; ++row)
    for (int col = 0; col < w; ++col) {
      const PlanePoint p = default_grid().forward(pixel_centre(gt, col, row));
      if (p.x < x0 + margin || p.x > x0 + side - margin || p.y > y1 - margin ||
          p.y < y1 - side + margin)
        continue;
      ++checked;
      max_err = std::max(max_err, std::abs(v[size_t(row) * w + col] - dem_field(p)));
    }
  EXPECT_GT(checked, 10000);
  // Bilinear interpolation alone errs by up to ~0.2 m here (h^2/8 |f''|); GDAL widens the kernel
  // where an output pixel covers more than one source pixel, which smooths a little more.
  EXPECT_LT(max_err, 1.0);
}

// gdalwarp (the program) on our rHEALPix export, onto exactly our EPSG:4326 grid.
void compare_with_gdalwarp(const std::string& layer, const std::string& resampling, double max_mean,
                           double max_max) {
  const std::string ours = export_to(layer, "EPSG:4326");
  const std::string plane = export_layer("gtiff", layer, "tif");
  const auto ds = open_raster(ours);
  ASSERT_TRUE(ds);
  double gt[6];
  ds->GetGeoTransform(gt);
  const int w = ds->GetRasterXSize(), h = ds->GetRasterYSize();
  const std::string theirs = temp_dir() + "/gdalwarp.tif";
  std::ostringstream cmd;
  cmd << std::setprecision(17) << "gdalwarp -q -t_srs EPSG:4326 -r " << resampling << " -te "
      << gt[0] << " " << gt[3] + h * gt[5] << " " << gt[0] + w * gt[1] << " " << gt[3] << " -ts "
      << w << " " << h << " " << plane << " " << theirs;
  ASSERT_EQ(std::system(cmd.str().c_str()), 0) << cmd.str();
  const auto ref = open_raster(theirs);
  ASSERT_TRUE(ref);
  const std::vector<double> a = read_band(*ds), b = read_band(*ref);
  ASSERT_EQ(a.size(), b.size());
  const double nodata = ds->GetRasterBand(1)->GetNoDataValue();
  double sum = 0, max_diff = 0, ours_off = 0, theirs_off = 0;
  int n = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    if (a[i] == nodata || b[i] == nodata) continue;
    const double d = std::abs(a[i] - b[i]);
    sum += d, max_diff = std::max(max_diff, d), ++n;
    if (layer != "dem") continue;
    const int col = int(i % size_t(w)), row = int(i / size_t(w));
    const double truth = dem_field(default_grid().forward(pixel_centre(gt, col, row)));
    ours_off += std::abs(a[i] - truth), theirs_off += std::abs(b[i] - truth);
  }
  ASSERT_GT(n, int(a.size() / 2));
  EXPECT_LE(sum / n, max_mean);
  EXPECT_LE(max_diff, max_max);
  // gdalwarp widens its kernel where an output pixel covers more than one source pixel, which
  // smooths the field; sampling at the pixel centre keeps closer to it.
  EXPECT_LE(ours_off, theirs_off);
}

TEST(GtiffWarp, AgreesWithGdalwarpOnOurRhealpixExport) {
  compare_with_gdalwarp("dem", "bilinear", 0.2, 1.0);
  // gdalwarp's default approximate transformer may move a pixel centre across a class edge.
  compare_with_gdalwarp("landcover", "near", 0.02, 2.0);
}

// A store of one cell of `info`'s layer, its tile from `value(sample)`; returns its path.
template <typename T, typename F>
std::string one_cell_store(const LayerInfo& info, F value) {
  const std::string path = temp_dir() + "/one.maquette";
  const CellId cell = export_fixture().dem_cells[0];
  auto store = Store::open(path, Store::Mode::Create);
  store->create_layer(info);
  store->put_tile(info.name, cell,
                  make_tile<T>(default_grid(), cell, kTileSize, 1,
                               [&](const TileSample& s, int) { return value(s); }));
  return path;
}

// float32 holds integers up to 2^24 exactly: an EPSG export of a uint32 layer beyond is refused
// (it would write 16777216 for 16777217), while the rHEALPix export writes it bit for bit.
TEST(GtiffWarp, RefusesIntegersFloat32CannotHold) {
  LayerInfo info = layer_info("count", DType::U32, 1, kTileSize, kLevel);
  info.semantics = Semantics::Categorical;  // nearest sampling
  const std::string store = one_cell_store<uint32_t>(
      info, [](const TileSample& s) { return 16777216 + uint32_t(s.col % 2); });
  const std::string out = temp_dir() + "/count.tif";
  const CliResult r =
      run_maquette("export gtiff " + store + " --layer count " + out + " --crs EPSG:4326");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("layer 'count' holds uint32 value 16777217"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--crs rhealpix"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));

  ASSERT_EQ(run_maquette("export gtiff " + store + " --layer count " + out).exit_code, 0);
  const auto ds = open_raster(out);
  ASSERT_TRUE(ds);
  const std::vector<double> v = read_band(*ds);
  EXPECT_EQ(*std::max_element(v.begin(), v.end()), 16777217.0);
}

}  // namespace
}  // namespace maquette::test
