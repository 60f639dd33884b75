// export png of the whole globe and of the polar caps, through the real program: the PNG's
// georeferencing (.aux.xml, .pgw: 10 decimals, so extents hold to 1e-6 degrees) read by GDAL, its
// pixels compared with the source raster at each pixel centre (PROJ gives the lon/lat of polar
// pixels), and clipping to --bbox.
#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "export_fixture.h"
#include "globe_fixture.h"
#include "run_cli.h"
#include "synthetic_raster.h"

namespace maquette::test {
namespace {

struct Png {
  Dataset ds;
  double gt[6] = {};
  int width = 0, height = 0;
  std::vector<double> band[4];
  bool opaque(int col, int row) const { return band[3][size_t(row) * width + col] == 255; }
  double value(int k, int col, int row) const { return band[k][size_t(row) * width + col]; }
};

Png export_png(const std::string& store, const std::string& layer, const std::string& extra) {
  Png png;
  const std::string out = temp_dir() + "/" + layer + ".png";
  const CliResult r = run_maquette("export png " + store + " --layer " + layer + " " + out +
                                   " --no-legend " + extra);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(out + ".aux.xml"));
  EXPECT_TRUE(std::filesystem::exists(out.substr(0, out.size() - 4) + ".pgw"));
  png.ds = open_raster(out);
  if (!png.ds) return png;
  EXPECT_EQ(png.ds->GetGeoTransform(png.gt), CE_None);
  png.width = png.ds->GetRasterXSize(), png.height = png.ds->GetRasterYSize();
  for (int k = 0; k < 4; ++k) png.band[k] = read_band(*png.ds, k + 1);
  return png;
}

std::string wkt(const Png& png) {
  char* text = nullptr;
  png.ds->GetSpatialRef()->exportToWkt(&text);
  std::string s = text;
  CPLFree(text);
  return s;
}

// world.tif's samples at the nearest pixel to a lon/lat.
class World {
 public:
  World() : ds_(open_raster(world_tif())) {
    w_ = ds_->GetRasterXSize(), h_ = ds_->GetRasterYSize();
    for (int k = 0; k < 3; ++k) bands_[k] = read_band(*ds_, k + 1);
  }
  double at(int k, double lon, double lat) const {
    const int c = std::clamp(int(std::floor((lon + 180) / 360 * w_)), 0, w_ - 1);
    const int r = std::clamp(int(std::floor((90 - lat) / 180 * h_)), 0, h_ - 1);
    return bands_[k][size_t(r) * w_ + c];
  }

 private:
  Dataset ds_;
  int w_ = 0, h_ = 0;
  std::vector<double> bands_[3];
};

struct Agreement {
  double opaque = 0;     // fraction of pixels drawn
  double mean_diff = 0;  // mean |PNG - world.tif| over drawn pixels and bands (0..255)
};

// Compares the PNG (drawn with --range 0 255, so unstretched) with world.tif at each pixel
// centre; `in_region` tells which pixels should be drawn.
Agreement compare_with_world(const Png& png,
                             const std::function<bool(double lon, double lat)>& in_region) {
  const World world;
  const Projector to_lonlat(wkt(png), "EPSG:4326");
  double sum = 0;
  int drawn = 0, expected = 0;
  for (int r = 0; r < png.height; ++r)
    for (int c = 0; c < png.width; ++c) {
      const auto [lon, lat] =
          to_lonlat(png.gt[0] + (c + 0.5) * png.gt[1], png.gt[3] + (r + 0.5) * png.gt[5]);
      if (!std::isfinite(lat) || !in_region(lon, lat)) continue;
      ++expected;
      if (!png.opaque(c, r)) continue;
      ++drawn;
      for (int k = 0; k < 3; ++k) sum += std::abs(png.value(k, c, r) - world.at(k, lon, lat));
    }
  return {double(drawn) / std::max(expected, 1), sum / std::max(3 * drawn, 1)};
}

bool everywhere(double, double) { return true; }

TEST(PngGlobe, WholeGlobeInLonLatAtEveryLevel) {
  if (world_tif().empty()) GTEST_SKIP() << "../shared/data/global/world.tif is absent";
  for (int level : {1, 2, 3}) {
    const Png png = export_png(world_store(level), "world", "--range 0 255");
    ASSERT_TRUE(png.ds) << level;
    OGRSpatialReference wgs84;
    wgs84.importFromEPSG(4326);
    const char* const ignore_axis_order[] = {"IGNORE_DATA_AXIS_TO_SRS_AXIS_MAPPING=YES", nullptr};
    EXPECT_TRUE(png.ds->GetSpatialRef()->IsSame(&wgs84, ignore_axis_order));
    EXPECT_NEAR(png.gt[0], -180, 1e-6);
    EXPECT_NEAR(png.gt[3], 90, 1e-6);
    EXPECT_NEAR(png.gt[0] + png.width * png.gt[1], 180, 1e-6);
    EXPECT_NEAR(png.gt[3] + png.height * png.gt[5], -90, 1e-6);
    const Agreement a = compare_with_world(png, everywhere);
    EXPECT_GT(a.opaque, 0.999) << level;
    EXPECT_LT(a.mean_diff, 12) << level;
  }
}

// The radius (metres) of a parallel in a polar LAEA frame.
double laea_radius(const Png& png, double lat) {
  const auto [x, y] = Projector("EPSG:4326", wkt(png))(0, lat);
  return std::hypot(x, y);
}

TEST(PngGlobe, PolarCapsInPolarLambertAzimuthal) {
  if (world_tif().empty()) GTEST_SKIP() << "../shared/data/global/world.tif is absent";
  for (const char* cap : {"S", "N"}) {
    const Png png =
        export_png(world_store(2), "world", std::string("--range 0 255 --cells ") + cap);
    ASSERT_TRUE(png.ds) << cap;
    // Near-square (a cap in lon/lat would be a long thin strip) and centred on the pole.
    EXPECT_NEAR(double(png.width) / png.height, 1.0, 0.1) << cap;
    const double pole = cap[0] == 'S' ? -90 : 90;
    const auto [px, py] = Projector("EPSG:4326", wkt(png))(0, pole);
    EXPECT_NEAR(px, 0, 1e-6);
    EXPECT_NEAR(py, 0, 1e-6);
    EXPECT_NEAR(png.gt[0] + png.width / 2.0 * png.gt[1], 0, 2 * png.gt[1]);
    const int centre = png.width / 2;
    EXPECT_TRUE(png.opaque(centre, png.height / 2)) << cap;
    // The face's edge runs at about 41.9 degrees from the equator; pixels drawn are the cap's.
    const Agreement a = compare_with_world(
        png, [&](double, double lat) { return std::abs(lat) > 45 && (lat > 0) == (pole > 0); });
    EXPECT_GT(a.opaque, 0.999) << cap;
    EXPECT_LT(a.mean_diff, 12) << cap;
  }
}

TEST(PngGlobe, ProjectionCanBeChosen) {
  if (world_tif().empty()) GTEST_SKIP() << "../shared/data/global/world.tif is absent";
  // The south cap forced into lon/lat: all longitudes, from the pole to the face's edge.
  const Png lonlat = export_png(world_store(1), "world", "--cells S --projection lonlat");
  ASSERT_TRUE(lonlat.ds);
  EXPECT_NEAR(lonlat.gt[0], -180, 1e-6);
  EXPECT_NEAR(lonlat.gt[0] + lonlat.width * lonlat.gt[1], 180, 1e-6);
  EXPECT_NEAR(lonlat.gt[3] + lonlat.height * lonlat.gt[5], -90, 1e-6);
  EXPECT_NEAR(lonlat.gt[3], -41.94, 0.05);  // the polar squares end at 41.94 degrees (geodetic)
  // A box of the northern tropics forced into the north polar frame.
  const Png polar = export_png(world_store(1), "world", "--bbox 0 0 20 20 --projection polar");
  ASSERT_TRUE(polar.ds);
  const auto [x, y] = Projector(wkt(polar), "EPSG:4326")(0, 0);
  EXPECT_NEAR(y, 90, 1e-6);  // the frame's origin is the north pole
}

TEST(PngGlobe, PipelineBboxAroundTheSouthPoleIsClippedToTheBox) {
  if (world_tif().empty()) GTEST_SKIP() << "../shared/data/global/world.tif is absent";
  const std::string dir = temp_dir();
  std::filesystem::copy_file(world_store(1), dir + "/world.mqt");
  std::ofstream(dir + "/p.json")
      << R"({"store": "world.mqt", "region": {"bbox": [-180, -90, 180, -85]},
      "level": 1, "steps": [{"op": "export",
      "params": {"format": "png", "layer": "world", "out": "cap.png", "range": [0, 255],
                 "legend": false, "bbox": [-180, -90, 180, -85]}}]})";
  const CliResult r = run_maquette("run " + dir + "/p.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  Png png;
  png.ds = open_raster(dir + "/cap.png");
  ASSERT_TRUE(png.ds);
  png.ds->GetGeoTransform(png.gt);
  png.width = png.ds->GetRasterXSize(), png.height = png.ds->GetRasterYSize();
  for (int k = 0; k < 4; ++k) png.band[k] = read_band(*png.ds, k + 1);
  // The frame is the square around the circle of latitude -85 degrees.
  const double radius = laea_radius(png, -85);
  EXPECT_NEAR(png.gt[0], -radius, 1e-3 * radius);
  EXPECT_NEAR(png.gt[3], radius, 1e-3 * radius);
  EXPECT_NEAR(png.width * png.gt[1], 2 * radius, 1e-3 * radius);
  const Agreement a = compare_with_world(png, [](double, double lat) { return lat <= -85; });
  EXPECT_GT(a.opaque, 0.999);
  EXPECT_LT(a.mean_diff, 12);
  // Nothing north of the box is drawn.
  int outside = 0;
  const Projector to_lonlat(wkt(png), "EPSG:4326");
  for (int row = 0; row < png.height; ++row)
    for (int col = 0; col < png.width; ++col)
      if (png.opaque(col, row))
        outside += to_lonlat(png.gt[0] + (col + 0.5) * png.gt[1],
                             png.gt[3] + (row + 0.5) * png.gt[5])[1] > -85;
  EXPECT_EQ(outside, 0);
}

TEST(PngGlobe, BboxIsTheExtentOfThePicture) {
  for (const auto& [box, west, east] :
       {std::tuple{"10 20 30 40", 10.0, 30.0}, std::tuple{"170 -10 -170 10", 170.0, 190.0}}) {
    const Png png = export_png(global_dem_store(), "dem", std::string("--bbox ") + box);
    ASSERT_TRUE(png.ds) << box;
    EXPECT_NEAR(png.gt[0], west, 1e-6) << box;
    EXPECT_NEAR(png.gt[0] + png.width * png.gt[1], east, 1e-6) << box;
    const double north = box[0] == '1' && box[1] == '0' ? 40 : 10;
    EXPECT_NEAR(png.gt[3], north, 1e-6) << box;
    EXPECT_NEAR(png.gt[3] + png.height * png.gt[5], north - 20, 1e-6) << box;
    int drawn = 0;
    for (int r = 0; r < png.height; ++r)
      for (int c = 0; c < png.width; ++c) drawn += png.opaque(c, r);
    EXPECT_EQ(drawn, png.width * png.height) << box;
  }
}

TEST(PngGlobe, GlobalDemWholeAndCaps) {
  const Png globe = export_png(global_dem_store(), "dem", "");
  ASSERT_TRUE(globe.ds);
  EXPECT_NEAR(globe.gt[3] + globe.height * globe.gt[5], -90, 1e-6);
  for (const char* box : {"-180 -90 180 -60", "-180 60 180 90"}) {
    const Png cap = export_png(global_dem_store(), "dem", std::string("--bbox ") + box);
    ASSERT_TRUE(cap.ds);
    EXPECT_NEAR(double(cap.width) / cap.height, 1.0, 0.01) << box;
    EXPECT_TRUE(cap.opaque(cap.width / 2, cap.height / 2)) << box;
  }
}

// Heights in metres are drawn with atlas tints by default: the sea blue, lowlands green (not the
// white of a stretched ramp's top), the highest ground light grey.
TEST(PngGlobe, HeightsGetHypsometricTints) {
  const Png png = export_png(global_dem_store(), "dem", "");
  ASSERT_TRUE(png.ds);
  int sea = 0, sea_blue = 0, low = 0, low_green = 0, high = 0, high_light = 0;
  for (int r = 0; r < png.height; ++r)
    for (int c = 0; c < png.width; ++c) {
      if (!png.opaque(c, r)) continue;
      const double h =
          global_height(png.gt[0] + (c + 0.5) * png.gt[1], png.gt[3] + (r + 0.5) * png.gt[5]);
      const double red = png.value(0, c, r), green = png.value(1, c, r), blue = png.value(2, c, r);
      if (h < -100) ++sea, sea_blue += blue > red && blue > green;
      if (h > 20 && h < 150) ++low, low_green += green > red && green > blue;
      if (h > 4300)
        ++high, high_light += std::min({red, green, blue}) > 170 &&
                              std::max({red, green, blue}) - std::min({red, green, blue}) < 25;
    }
  ASSERT_GT(sea, 1000);
  ASSERT_GT(low, 100);
  ASSERT_GT(high, 100);
  EXPECT_GT(double(sea_blue) / sea, 0.99);
  EXPECT_GT(double(low_green) / low, 0.99);
  EXPECT_GT(double(high_light) / high, 0.95);
}

}  // namespace
}  // namespace maquette::test
