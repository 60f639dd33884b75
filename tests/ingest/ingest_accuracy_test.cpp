// Ingested samples against the analytic fields the test rasters were made from: projected (UTM),
// categorical, the whole globe, across the antimeridian, over a pole.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <optional>
#include <set>

#include "core/error.h"
#include "ingest_fixture.h"
#include "synthetic_raster.h"

namespace maquette::test {
namespace {

constexpr double kUtmE0 = 500000 - 6000, kUtmN0 = 4120000 + 6000;  // UTM 12N, near Zion

// A smooth field in UTM metres: gradient up to ~0.4 per 30 m pixel.
double utm_field(double e, double n) {
  return 500 + 10 * std::sin(2 * M_PI * e / 5000) * std::cos(2 * M_PI * n / 7000);
}

// Classes in 600 m blocks (20 pixels); `border` is the distance to the nearest block edge.
int utm_class(double e, double n, double* border = nullptr) {
  const double be = std::floor(e / 600), bn = std::floor(n / 600);
  if (border)
    *border = std::min({e - be * 600, (be + 1) * 600 - e, n - bn * 600, (bn + 1) * 600 - n});
  return 1 + int(std::fmod(be + 3 * bn + 700, 7.0));
}

RasterSpec utm_spec(const std::string& type) {
  RasterSpec s;
  s.width = s.height = 400;
  s.geotransform = {kUtmE0, 30, 0, kUtmN0, 0, -30};
  s.crs = "EPSG:32612";
  s.type = type;
  return s;
}

// Ingests the UTM field and returns the largest and mean error of the samples well inside it.
void check_utm_field(std::optional<Resampling> resampling, double max_error, double mean_error) {
  const std::string dir = temp_dir(), tif = dir + "/utm.tif";
  write_raster(tif, utm_spec("Float32"), [](int, double e, double n) { return utm_field(e, n); });
  RasterIngestOptions o;
  o.layer = "f";
  o.as = "climate";
  o.resampling = resampling;
  const auto store = ingest(dir, "utm", {tif}, o);
  const LayerInfo info = store->require_layer("f");
  EXPECT_EQ(info.level, 11);  // 17.6 m pixels, the coarsest level not coarser than 30 m
  EXPECT_EQ(info.dtype, DType::F32);
  EXPECT_EQ(info.provenance["resampling"],
            resampling_name(resampling.value_or(Resampling::Bilinear)));
  const Projector to_utm("EPSG:4326", "EPSG:32612");
  double max_err = 0, sum = 0;
  int64_t n = 0;
  for_each_sample(*store, "f", [&](CellId, LonLat p, const float* v) {
    const auto [e, nn] = to_utm(p.lon, p.lat);
    // Inside the raster by more than a pixel: bilinear with all four neighbours.
    const bool inside =
        e > kUtmE0 + 45 && e < kUtmE0 + 12000 - 45 && nn < kUtmN0 - 45 && nn > kUtmN0 - 12000 + 45;
    const bool outside =
        e < kUtmE0 - 1 || e > kUtmE0 + 12001 || nn > kUtmN0 + 1 || nn < kUtmN0 - 12001;
    if (outside) {
      EXPECT_TRUE(std::isnan(v[0])) << e << " " << nn;
    }
    if (!inside) return;
    ASSERT_FALSE(std::isnan(v[0]));
    const double err = std::abs(v[0] - utm_field(e, nn));
    max_err = std::max(max_err, err);
    sum += err;
    ++n;
  });
  ASSERT_GT(n, 100000);
  EXPECT_LT(max_err, max_error);
  EXPECT_LT(sum / double(n), mean_error);
}

TEST(IngestAccuracy, SmoothFieldInUtmWithinTheBilinearBound) {
  // Bilinear: h^2/8 |f''| ~ 0.02; the approximate transform adds up to 1/8 pixel x gradient.
  check_utm_field(std::nullopt, 0.06, 0.01);
}

TEST(IngestAccuracy, SmoothFieldInUtmCubic) {
  // Cubic convolution is exact to the third order: only the transform's error is left.
  check_utm_field(Resampling::Cubic, 0.05, 0.005);
}

TEST(IngestAccuracy, CategoricalClassesExactAwayFromBorders) {
  const std::string dir = temp_dir(), tif = dir + "/classes.tif";
  RasterSpec spec = utm_spec("Byte");
  spec.nodata = 0;
  spec.categories = {"none", "water", "forest", "shrub", "grass", "crops", "urban", "ice"};
  spec.colour_table = true;
  write_raster(tif, spec, [](int, double e, double n) { return utm_class(e, n); });
  RasterIngestOptions o;
  o.layer = "lc";
  o.as = "landcover";
  const auto store = ingest(dir, "lc", {tif}, o);
  const LayerInfo info = store->require_layer("lc");
  EXPECT_EQ(info.dtype, DType::U8);
  EXPECT_EQ(info.semantics, Semantics::Categorical);
  EXPECT_EQ(info.nodata, 0.0);
  EXPECT_EQ(info.provenance["resampling"], "nearest");
  EXPECT_EQ(info.provenance["classes"]["1"]["name"], "water");
  EXPECT_EQ(info.provenance["classes"]["1"]["color"], "#0a140f");
  const Projector to_utm("EPSG:4326", "EPSG:32612");
  int64_t checked = 0;
  for_each_sample(*store, "lc", [&](CellId, LonLat p, const float* v) {
    const auto [e, n] = to_utm(p.lon, p.lat);
    double border = 0;
    const int cls = utm_class(e, n, &border);
    const bool inside =
        e > kUtmE0 + 30 && e < kUtmE0 + 12000 - 30 && n < kUtmN0 - 30 && n > kUtmN0 - 12000 + 30;
    if (!inside || border < 30) return;
    ASSERT_EQ(int(v[0]), cls) << p.lon << " " << p.lat;
    ++checked;
  });
  EXPECT_GT(checked, 100000);
}

TEST(IngestAccuracy, ScaleAndOffsetGiveFloat32) {
  const std::string dir = temp_dir(), tif = dir + "/scaled.tif";
  RasterSpec spec = utm_spec("UInt16");
  spec.nodata = 0;
  spec.scale = 0.1;
  spec.offset = 5;
  write_raster(tif, spec, [](int, double e, double) { return e < kUtmE0 + 6000 ? 1000 : 0; });
  RasterIngestOptions o;
  o.layer = "s";
  o.as = "imagery";  // would keep uint16 without the scale
  const auto store = ingest(dir, "scaled", {tif}, o);
  EXPECT_EQ(store->require_layer("s").dtype, DType::F32);
  int64_t valid = 0;
  for_each_sample(*store, "s", [&](CellId, LonLat, const float* v) {
    if (std::isnan(v[0])) return;
    ASSERT_NEAR(v[0], 105.0f, 1e-4f);  // nodata (0) never mixed in
    ++valid;
  });
  EXPECT_GT(valid, 100000);
}

// Ingests a lon/lat raster of sphere_field and checks every valid sample against it.
// Samples within a pixel of the raster's edges are left out of the error (beyond the last row or
// column of pixel centres only one is left to interpolate from); a 360-degree raster wraps.
void check_lonlat_raster(const RasterSpec& spec, double max_error, std::set<int>* faces,
                         int64_t* samples) {
  const auto& gt = spec.geotransform;
  const double north = gt[3] + gt[5], south = gt[3] + (spec.height - 1) * gt[5];
  const double width = spec.width * gt[1];
  const auto interior = [&](LonLat p) {
    const double lon = gt[0] + std::fmod(std::fmod(p.lon - gt[0], 360.0) + 360.0, 360.0);
    return p.lat < north && p.lat > south &&
           (width >= 360 || (lon > gt[0] + gt[1] && lon < gt[0] + width - gt[1]));
  };
  const std::string dir = temp_dir(), tif = dir + "/ll.tif";
  write_raster(tif, spec, [](int, double lon, double lat) { return sphere_field(lon, lat); });
  RasterIngestOptions o;
  o.layer = "f";
  o.as = "raster";
  const auto store = ingest(dir, "ll", {tif}, o);
  double worst = 0;
  for_each_sample(*store, "f", [&](CellId cell, LonLat p, const float* v) {
    if (std::isnan(v[0])) return;
    faces->insert(cell.face());
    ++*samples;
    if (interior(p)) worst = std::max(worst, std::abs(v[0] - sphere_field(p.lon, p.lat)));
  });
  EXPECT_LT(worst, max_error);
}

TEST(IngestAccuracy, WholeGlobeCoversAllSixFaces) {
  RasterSpec spec;
  spec.width = 360;
  spec.height = 180;
  spec.geotransform = {-180, 1, 0, 90, 0, -1};
  spec.crs = "EPSG:4326";
  std::set<int> faces;
  int64_t samples = 0;
  // 1-degree pixels, field amplitude ~370: bilinear error h^2/8 |f''| ~ 0.04, and the
  // approximate transform's 1/8 pixel x gradient (6.5 per pixel) ~ 0.8.
  check_lonlat_raster(spec, 0.9, &faces, &samples);
  EXPECT_EQ(faces.size(), 6u);
  EXPECT_EQ(samples, 6 * 256 * 256);  // no hole anywhere: poles and antimeridian included
}

// A 1-degree lon/lat raster of the whole globe in `dir`; returns its path.
std::string write_globe(const std::string& dir) {
  RasterSpec spec;
  spec.width = 360;
  spec.height = 180;
  spec.geotransform = {-180, 1, 0, 90, 0, -1};
  spec.crs = "EPSG:4326";
  const std::string tif = dir + "/globe.tif";
  write_raster(tif, spec, [](int, double lon, double lat) { return sphere_field(lon, lat); });
  return tif;
}

// A global source limited to a small --bbox at a fine level: only the bbox's cells, not the globe
// covered first (2.5 billion cells at level 14); a bbox across the antimeridian takes both sides.
TEST(IngestAccuracy, GlobalSourceInASmallBboxAtAFineLevel) {
  const std::string dir = temp_dir(), tif = write_globe(dir);
  for (const std::array<double, 4> bbox : {std::array<double, 4>{-0.146, 51.507, -0.128, 51.519},
                                           std::array<double, 4>{179.995, -0.01, -179.995, 0.01}}) {
    RasterIngestOptions o;
    o.layer = "f";
    o.as = "raster";
    o.level = 14;
    o.bbox = bbox;
    const auto store = ingest(dir, "small" + std::to_string(int(bbox[0])), {tif}, o);
    const std::vector<CellId> want =
        default_grid().cover_bbox(bbox[0], bbox[1], bbox[2], bbox[3], 14, Containment::Overlap);
    EXPECT_GT(want.size(), 4u);
    EXPECT_EQ(store->tile_cells("f"), want) << bbox[0];
  }
}

// A box around the globe is refused by the estimate, before the cover is made (a box edge
// follows a parallel: the box taken as a geodesic polygon has area 0, and the cover of 1e9
// cells ran out of memory).
TEST(IngestAccuracy, GlobalBboxAtAFineLevelIsRefusedBeforeCovering) {
  const std::string dir = temp_dir(), tif = write_globe(dir);
  for (const std::array<double, 4> bbox :
       {std::array<double, 4>{-180, -60, 180, 60}, std::array<double, 4>{-180, -90, 180, 90}}) {
    RasterIngestOptions o;
    o.layer = "f";
    o.as = "raster";
    o.level = 14;
    o.bbox = bbox;
    try {
      ingest(dir, "global" + std::to_string(int(bbox[1])), {tif}, o);
      ADD_FAILURE() << "a global box at level 14 was not refused";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("the ingest would write"), std::string::npos)
          << e.what();
    }
  }
}

TEST(IngestAccuracy, RasterAcrossTheAntimeridian) {
  RasterSpec spec;
  spec.width = 400;
  spec.height = 200;
  spec.geotransform = {170, 0.05, 0, 5, 0, -0.05};  // lon 170..190, lat -5..5
  spec.crs = "EPSG:4326";
  std::set<int> faces;
  int64_t samples = 0;
  // 0.05-degree pixels: gradient 0.33 per pixel, so 1/8 pixel ~ 0.04.
  check_lonlat_raster(spec, 0.05, &faces, &samples);
  EXPECT_TRUE(faces.count(4) && faces.count(1)) << "faces R and O on both sides";
  EXPECT_GT(samples, 100000);
}

TEST(IngestAccuracy, PolarStereographicOverTheSouthPole) {
  const std::string dir = temp_dir(), tif = dir + "/polar.tif";
  RasterSpec spec;
  spec.width = spec.height = 200;
  spec.geotransform = {-1000000, 10000, 0, 1000000, 0, -10000};
  spec.crs = "EPSG:3031";
  const Projector to_ll("EPSG:3031", "EPSG:4326");
  write_raster(tif, spec, [&](int, double x, double y) {
    const auto [lon, lat] = to_ll(x, y);
    return sphere_field(lon, lat);
  });
  RasterIngestOptions o;
  o.layer = "f";
  const auto store = ingest(dir, "polar", {tif}, o);
  const Projector to_ps("EPSG:4326", "EPSG:3031");
  double worst = 0;
  int64_t n = 0;
  bool pole = false;
  for_each_sample(*store, "f", [&](CellId cell, LonLat p, const float* v) {
    EXPECT_EQ(cell.face(), 5);
    const auto [x, y] = to_ps(p.lon, p.lat);
    if (std::abs(x) > 980000 || std::abs(y) > 980000) return;
    ASSERT_FALSE(std::isnan(v[0])) << p.lon << " " << p.lat;
    pole = pole || p.lat < -89.9;
    worst = std::max(worst, std::abs(v[0] - sphere_field(p.lon, p.lat)));
    ++n;
  });
  EXPECT_TRUE(pole);
  EXPECT_GT(n, 10000);
  EXPECT_LT(worst, 0.5);
}

}  // namespace
}  // namespace maquette::test
