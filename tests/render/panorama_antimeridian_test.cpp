// `maquette render panorama` straight down on the antimeridian: a hill from 179.5 E to 179.5 W
// draped with imagery of one colour. Every terrain pixel's lon guide lies in the DEM's box (in
// [-180, 180]: the offsets from the eye's lon 180 wrapped), and
// every terrain pixel shows the imagery's colour (red well above green) times its shading: the
// triangles across lon 180 once interpolated their corners' 179.99 and -179.99 to lon ~0, a lon
// guide half the globe away and a stripe of untextured grey (R = G = B) one sample wide.
#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "run_cli.h"
#include "synthetic_raster.h"

namespace maquette {
namespace {

constexpr int kWidth = 240, kHeight = 160;

TEST(PanoramaAntimeridian, GuidesAndTextureContinueAcrossLon180) {
  const std::string dir = test::temp_dir(), store = dir + "/s.mqt";
  // A hill on lon 180 with ridges: a flat DEM did not show the fault here.
  test::write_raster(
      dir + "/dem.tif", test::lonlat_raster(179.5, -15.5, 400, 0.0025, "Float32"),
      [](int, double lon, double lat) {
        const double u = lon - 179.5, v = lat + 16.5;
        return 200 + 1500 * std::exp(-((u - 0.5) * (u - 0.5) + (v - 0.5) * (v - 0.5)) / 0.02) +
               300 * std::sin(6 * std::numbers::pi * u) * std::sin(4 * std::numbers::pi * v) +
               200 * v;
      });
  test::RasterSpec rgb = test::lonlat_raster(179.5, -15.5, 400, 0.0025, "Byte");
  rgb.bands = 3;
  test::write_raster(dir + "/rgb.tif", rgb, [](int band, double, double) {
    return band == 1 ? 200 : band == 2 ? 60 : 30;
  });
  for (const std::string& ingest :
       {"--layer dem --as dem --vertical-datum ellipsoid " + dir + "/dem.tif",
        "--layer rgb --as imagery " + dir + "/rgb.tif"}) {
    const auto r = test::run_maquette("-q ingest " + store + " " + ingest);
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  const std::string out = dir + "/down.png";
  const auto r = test::run_maquette(
      "-q render panorama " + store + " " + out +
      " --dem dem --texture rgb --no-stretch --camera 180 -16 30000 --pitch -90 --fov 60 --size " +
      std::to_string(kWidth) + " " + std::to_string(kHeight) + " --haze-distance 1e12");
  ASSERT_EQ(r.exit_code, 0) << r.err;

  std::unique_ptr<GDALDataset> picture(GDALDataset::Open(out.c_str(), GDAL_OF_RASTER)),
      guides(GDALDataset::Open((dir + "/down-guides.tif").c_str(), GDAL_OF_RASTER));
  ASSERT_TRUE(picture && guides);
  std::vector<uint8_t> rgb_pixels(size_t(kWidth) * kHeight * 3);
  ASSERT_EQ(picture->RasterIO(GF_Read, 0, 0, kWidth, kHeight, rgb_pixels.data(), kWidth, kHeight,
                              GDT_Byte, 3, nullptr, 3, 3 * kWidth, 1, nullptr),
            CE_None);
  std::vector<double> lon(size_t(kWidth) * kHeight);
  ASSERT_EQ(guides->GetRasterBand(3)->RasterIO(GF_Read, 0, 0, kWidth, kHeight, lon.data(), kWidth,
                                               kHeight, GDT_Float64, 0, 0),
            CE_None);
  int terrain = 0, west = 0, east = 0, off_box = 0, grey = 0;
  for (size_t i = 0; i < lon.size(); ++i) {
    if (std::isnan(lon[i])) continue;
    ++terrain;
    (lon[i] > 0 ? west : east) += 1;
    if (std::abs(lon[i]) < 179.5 || std::abs(lon[i]) > 180) ++off_box;  // in [-180, 180] too
    if (rgb_pixels[3 * i] < rgb_pixels[3 * i + 1] + 40) ++grey;
  }
  EXPECT_EQ(terrain, kWidth * kHeight);  // the DEM fills the view
  EXPECT_GT(west, terrain / 3);
  EXPECT_GT(east, terrain / 3);
  EXPECT_EQ(off_box, 0);
  EXPECT_EQ(grey, 0);
}

}  // namespace
}  // namespace maquette
