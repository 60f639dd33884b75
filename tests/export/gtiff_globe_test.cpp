// export gtiff of a whole-globe DEM (written with GDAL, ingested by the program): EPSG:4326 from
// pole to pole, the rHEALPix plane with its six faces, --bbox clipping (PROJ is the oracle for
// the plane position of the box) and the --max-mib size guard.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "export_fixture.h"
#include "globe_fixture.h"
#include "run_cli.h"
#include "synthetic_raster.h"

namespace maquette::test {
namespace {

constexpr const char* kRhealpix =
    "+proj=rhealpix +ellps=WGS84 +north_square=0 +south_square=0 +units=m +no_defs";

struct Geotiff {
  Dataset ds;
  double gt[6] = {};
  int width = 0, height = 0;
  std::vector<double> values;
};

Geotiff export_gtiff(const std::string& extra) {
  Geotiff g;
  const std::string out = temp_dir() + "/dem.tif";
  const CliResult r =
      run_maquette("export gtiff " + global_dem_store() + " --layer dem " + out + " " + extra);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  g.ds = open_raster(out);
  if (!g.ds) return g;
  g.ds->GetGeoTransform(g.gt);
  g.width = g.ds->GetRasterXSize(), g.height = g.ds->GetRasterYSize();
  g.values = read_band(*g.ds);
  return g;
}

TEST(GtiffGlobe, Epsg4326ReachesBothPoles) {
  const Geotiff g = export_gtiff("--crs EPSG:4326 --resolution 0.5");
  ASSERT_TRUE(g.ds);
  EXPECT_NEAR(g.gt[0], -180, 1e-9);
  EXPECT_NEAR(g.gt[3], 90, 1e-9);
  EXPECT_NEAR(g.gt[0] + g.width * g.gt[1], 180, 1e-9);
  EXPECT_NEAR(g.gt[3] + g.height * g.gt[5], -90, 1e-9);
  std::vector<double> errors;
  int missing = 0;
  for (int row = 0; row < g.height; ++row)
    for (int col = 0; col < g.width; ++col) {
      const double v = g.values[size_t(row) * g.width + col];
      if (!std::isfinite(v)) {
        ++missing;
        continue;
      }
      const double lon = g.gt[0] + (col + 0.5) * g.gt[1], lat = g.gt[3] + (row + 0.5) * g.gt[5];
      errors.push_back(std::abs(v - global_height(lon, lat)));
    }
  EXPECT_EQ(missing, 0);
  std::sort(errors.begin(), errors.end());
  // Each pixel is sampled through the grid, across face seams (sampling the rHEALPix plane raster
  // read one side only of the seams that are not side by side in the plane: 5.0 m at the 99th
  // percentile, 25 m at worst). What is left is the ingest's and the export's interpolation of the
  // 0.5-degree source, which has no row beyond 89.75 degrees: 1.2 m and 7.2 m.
  EXPECT_LT(errors[errors.size() * 99 / 100], 2.0);
  EXPECT_LT(errors.back(), 10);
}

TEST(GtiffGlobe, RhealpixPlaneHoldsTheSixFaces) {
  const Geotiff g = export_gtiff("--level 1");
  ASSERT_TRUE(g.ds);
  EXPECT_EQ(g.width * 3, g.height * 4);  // four faces wide, three tall
  const Projector to_lonlat(kRhealpix, "EPSG:4326");
  int data = 0;
  double max_err = 0;
  for (int row = 0; row < g.height; row += 7)
    for (int col = 0; col < g.width; col += 7) {
      const double v = g.values[size_t(row) * g.width + col];
      if (!std::isfinite(v)) continue;
      ++data;
      const auto [lon, lat] =
          to_lonlat(g.gt[0] + (col + 0.5) * g.gt[1], g.gt[3] + (row + 0.5) * g.gt[5]);
      max_err = std::max(max_err, std::abs(v - global_height(lon, lat)));
    }
  EXPECT_NEAR(double(data) / ((g.width / 7 + 1) * (g.height / 7 + 1)), 0.5, 0.02);
  EXPECT_LT(max_err, 300);  // level-1 overview pixels are ~80 km
}

TEST(GtiffGlobe, RhealpixBboxIsClippedToTheBox) {
  const Geotiff g = export_gtiff("--bbox 10 20 30 40");
  ASSERT_TRUE(g.ds);
  const Projector to_plane("EPSG:4326", kRhealpix);
  const auto [x0, y0] = to_plane(10, 20);
  const auto [x1, y1] = to_plane(30, 40);
  const double pixel = g.gt[1];
  // The box on whole pixels of the plane: each edge at most a pixel outside the box.
  EXPECT_LE(g.gt[0], x0 + 1e-6);
  EXPECT_GT(g.gt[0], x0 - pixel);
  EXPECT_GE(g.gt[0] + g.width * pixel, x1 - 1e-6);
  EXPECT_LT(g.gt[0] + g.width * pixel, x1 + pixel);
  EXPECT_GE(g.gt[3], y1 - 1e-6);
  EXPECT_LT(g.gt[3], y1 + pixel);
  EXPECT_LE(g.gt[3] + g.height * g.gt[5], y0 + 1e-6);
  EXPECT_GT(g.gt[3] + g.height * g.gt[5], y0 - pixel);
  // Data exactly at the pixels whose centres lie in the box (a pixel's width of doubt at edges).
  const Projector to_lonlat(kRhealpix, "EPSG:4326");
  int inside = 0, wrong = 0;
  for (int row = 0; row < g.height; ++row)
    for (int col = 0; col < g.width; ++col) {
      const auto [lon, lat] =
          to_lonlat(g.gt[0] + (col + 0.5) * g.gt[1], g.gt[3] + (row + 0.5) * g.gt[5]);
      const bool data = std::isfinite(g.values[size_t(row) * g.width + col]);
      const double margin = 1e-6;
      if (lon > 10 + margin && lon < 30 - margin && lat > 20 + margin && lat < 40 - margin)
        ++inside, wrong += !data;
      else if (lon < 10 - margin || lon > 30 + margin || lat < 20 - margin || lat > 40 + margin)
        wrong += data;
    }
  EXPECT_GE(inside, (g.width - 2) * (g.height - 2));
  EXPECT_EQ(wrong, 0);
}

// Around a pole the box is a disc in the plane: its square's corners hold no data.
TEST(GtiffGlobe, RhealpixPolarBoxKeepsOnlyTheBox) {
  const Geotiff g = export_gtiff("--bbox -180 60 180 90");
  ASSERT_TRUE(g.ds);
  const Projector to_lonlat(kRhealpix, "EPSG:4326");
  int inside = 0, outside_with_data = 0, inside_without_data = 0;
  for (int row = 0; row < g.height; ++row)
    for (int col = 0; col < g.width; ++col) {
      const auto [lon, lat] =
          to_lonlat(g.gt[0] + (col + 0.5) * g.gt[1], g.gt[3] + (row + 0.5) * g.gt[5]);
      const bool data = std::isfinite(g.values[size_t(row) * g.width + col]);
      // Half a pixel of tolerance at the circle (PROJ and the grid may round differently).
      if (lat >= 60.01) ++inside, inside_without_data += !data;
      if (lat < 59.99) outside_with_data += data;
    }
  EXPECT_GT(inside, g.width * g.height / 2);
  EXPECT_EQ(inside_without_data, 0);
  EXPECT_EQ(outside_with_data, 0);
}

TEST(GtiffGlobe, MaxMibRefusesWithAnEstimate) {
  for (const char* crs : {"rhealpix", "EPSG:4326"}) {
    const std::string out = temp_dir() + "/big.tif";
    CliResult r = run_maquette("export gtiff " + global_dem_store() + " --layer dem " + out +
                               " --crs " + crs + " --max-mib 1");
    EXPECT_NE(r.exit_code, 0) << crs;
    EXPECT_NE(r.err.find("MiB before compression"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("above the limit of 1 MiB"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out));
    r = run_maquette("export gtiff " + global_dem_store() + " --layer dem " + out + " --crs " +
                     crs + " --max-mib 1 --force");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(std::filesystem::exists(out));
  }
}

}  // namespace
}  // namespace maquette::test
