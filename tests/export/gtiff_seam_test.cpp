// export gtiff --crs EPSG:NNNN across face seams that are not side by side in the rHEALPix
// plane: the north cap's edge with face Q (latitude 41.94 degrees), the antimeridian between
// faces R and O, and the cube corner where N, Q and R meet. A steep analytic DEM (written with
// GDAL, ingested by the program) is exported to EPSG:4326 and to UTM; every output pixel is
// compared with the field at its centre (PROJ gives the lon/lat of UTM pixels). Sampling the plane
// raster read only one side of such a seam (errors of ~27 m here, a third of a pixel times the
// slope); sampling across the seam leaves only bilinear interpolation's error.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>

#include "export_fixture.h"
#include "run_cli.h"
#include "synthetic_raster.h"

namespace maquette::test {
namespace {

constexpr double kDeg = std::numbers::pi / 180;
// The latitude of the polar caps' edge: authalic sin(beta) = 2/3.
constexpr double kCapEdge = 41.9379;

// Heights in metres: 1000 +- 800 m waves of about 55 km, slopes up to ~90 m per km.
double field(double lon, double lat) {
  return 1000 + 800 * std::sin(2 * std::numbers::pi * lon / 0.5) *
                    std::cos(2 * std::numbers::pi * lat / 0.45 + 0.3);
}

// A store holding layer "dem": the field on a 0.001-degree lon/lat raster of 1.2 x 1.2 degrees
// with its top-left corner at (west, north), ingested at level 8 (64-sample tiles: ~610 m
// pixels).
std::string seam_store(const std::string& name, double west, double north) {
  const std::string dir = temp_dir();
  const std::string tif = dir + "/" + name + ".tif", store = dir + "/" + name + ".mqt";
  write_raster(tif, lonlat_raster(west, north, 1200, 0.001, "Float32"),
               [](int, double lon, double lat) { return field(lon, lat); });
  const CliResult r = run_maquette("ingest " + store + " --layer dem --as dem " + tif +
                                   " --level 8 --tile-size 64 --vertical-datum ellipsoid");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return store;
}

struct Errors {
  double max = 0, max_near_seam = 0;
  int pixels = 0, near_seam = 0, missing = 0;
};

// Exports `store`'s dem with `options` and compares every pixel with the field at its centre;
// near_seam(lon, lat) tells which pixels lie within a few layer pixels of the seam.
Errors export_errors(const std::string& store, const std::string& options, const char* crs,
                     bool (*near_seam)(double lon, double lat)) {
  const std::string out = temp_dir() + "/dem.tif";
  const CliResult r = run_maquette("export gtiff " + store + " --layer dem " + out + " --crs " +
                                   crs + " " + options);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  Errors e;
  const auto ds = open_raster(out);
  if (!ds) return e;
  double gt[6];
  ds->GetGeoTransform(gt);
  const int w = ds->GetRasterXSize(), h = ds->GetRasterYSize();
  const std::vector<double> v = read_band(*ds);
  const double nodata = ds->GetRasterBand(1)->GetNoDataValue();
  const Projector to_lonlat(crs, "EPSG:4326");
  for (int row = 0; row < h; ++row)
    for (int col = 0; col < w; ++col) {
      const double value = v[size_t(row) * w + col];
      if (value == nodata || !std::isfinite(value)) {
        ++e.missing;
        continue;
      }
      auto [lon, lat] = to_lonlat(gt[0] + (col + 0.5) * gt[1], gt[3] + (row + 0.5) * gt[5]);
      const double err = std::abs(value - field(std::remainder(lon, 360.0), lat));
      ++e.pixels;
      e.max = std::max(e.max, err);
      if (near_seam(lon, lat)) ++e.near_seam, e.max_near_seam = std::max(e.max_near_seam, err);
    }
  return e;
}

bool near_cap_edge(double, double lat) { return std::abs(lat - kCapEdge) < 0.02; }
bool near_antimeridian(double lon, double) { return std::abs(std::remainder(lon, 360.0)) > 179.98; }
// Where faces N, Q and R meet (only three faces meet at a cube corner).
bool near_corner(double lon, double lat) {
  return std::abs(lon - 90) < 0.03 && std::abs(lat - kCapEdge) < 0.03;
}

// Bilinear interpolation on pixels of side h errs by up to h^2/8 (|f_xx| + |f_yy|): here the
// waves are ~41 km long in longitude at 42 degrees, 50 km in latitude, and pixels up to ~0.7 km
// on the ground, so up to ~2 m. Reading one side of the seam errs by the slope times the distance
// to it: up to ~27 m.
constexpr double kTolerance = 2.0;

// Exports the box (W S E N) of `store` to EPSG:4326 and to UTM zone `utm`, checking every pixel.
void expect_seam_within_tolerance(const std::string& store, const std::string& bbox,
                                  const std::string& utm, bool (*near_seam)(double, double),
                                  double tolerance = kTolerance) {
  for (const auto& [crs, resolution] :
       {std::pair{std::string("EPSG:4326"), "0.002"}, std::pair{utm, "200"}}) {
    const Errors e = export_errors(store, "--bbox " + bbox + " --resolution " + resolution,
                                   crs.c_str(), near_seam);
    SCOPED_TRACE(crs);
    std::cout << crs << ": max error " << e.max << " m, " << e.max_near_seam << " m near the seam ("
              << e.near_seam << " of " << e.pixels << " pixels)\n";
    EXPECT_GT(e.pixels, 100000);
    EXPECT_GT(e.near_seam, 500);
    EXPECT_LT(e.max_near_seam, tolerance);
    EXPECT_LT(e.max, tolerance);
  }
}

TEST(GtiffSeam, PolarCapEdgeInLonLatAndUtm) {
  const std::string store = seam_store("cap", 44.4, 42.5);  // lat 41.3..42.5, across 41.94
  expect_seam_within_tolerance(store, "44.5 41.4 45.5 42.4", "EPSG:32638", near_cap_edge);
}

TEST(GtiffSeam, AntimeridianInLonLatAndUtm) {
  const std::string store = seam_store("antimeridian", 179.4, 0.6);  // lon 179.4..180.6
  expect_seam_within_tolerance(store, "179.5 -0.5 -179.5 0.5", "EPSG:32660", near_antimeridian);
}

TEST(GtiffSeam, CubeCornerInLonLatAndUtm) {
  const std::string store = seam_store("corner", 89.4, 42.5);  // around (90, 41.94)
  // Longitude 90 is also a diagonal of the cap's square, a crease of the projection, where
  // bilinear interpolation in the plane errs a little more (up to 2.7 m, 0.3 degrees inside
  // the cap).
  expect_seam_within_tolerance(store, "89.5 41.4 90.5 42.4", "EPSG:32646", near_corner, 3.0);
}

}  // namespace
}  // namespace maquette::test
