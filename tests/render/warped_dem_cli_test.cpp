// `maquette render fit --warped-dem`: a painting of a world its painter bulged (the DEM of round
// hills on a ramp moved by a known displacement field, a 600 m bulge), clicked at points of the
// ground between the hills, where the tests' own pinhole in PROJ's frame puts them moved; the
// hills' summits held out. The store's DEM warped by the fit and drawn by `render panorama` under
// the fitted camera puts each summit where the painting (the moved DEM drawn under the true camera)
// has it; the DEM as it was, under the same camera, misses. Far from the clicks the warped layer is
// the DEM bit for bit (both exported through GDAL); bad names and input write nothing.
#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <vector>

#include "proj_enu.h"
#include "run_cli.h"
#include "store/store.h"
#include "synthetic_raster.h"
#include "test_camera.h"

namespace maquette {
namespace {

using nlohmann::json;
using test::run_maquette;

// The hills: 9 x 6 summits 250 m above a ramp rising 200 m per degree of longitude eastwards.
constexpr int kHillsEast = 9, kHillsNorth = 6;
constexpr double kHillLon0 = 10.0, kHillLat0 = 45.03, kHillDLon = 0.04, kHillDLat = 0.035;
constexpr double kHillHeight = 250, kHillSigma = 300;  // metres
double ramp(double lon) { return 100 + 200 * (lon - 10); }
double dem_height(double lon, double lat) {
  constexpr double kMetresPerDegree = 111320;
  double h = ramp(lon);
  for (int i = 0; i < kHillsEast; ++i)
    for (int j = 0; j < kHillsNorth; ++j) {
      const double e = (lon - kHillLon0 - kHillDLon * i) * kMetresPerDegree *
                       std::cos(45 * std::numbers::pi / 180),
                   n = (lat - kHillLat0 - kHillDLat * j) * kMetresPerDegree;
      h += kHillHeight * std::exp(-(e * e + n * n) / (2 * kHillSigma * kHillSigma));
    }
  return h;
}

// The painter's bulge, degrees: up to 600 m east and 300 m north, about (10.18, 45.09), falling
// off over some 6 km.
std::array<double, 2> bulge(double lon, double lat) {
  const double e = (lon - 10.18) / 0.076, n = (lat - 45.09) / 0.054;
  const double w = std::exp(-(e * e + n * n) / 2);
  return {600 * w / 78700, 300 * w / 111320};
}
// Where the painted world has the DEM's point (lon, lat): the fixed point of g' = g + bulge(g').
std::array<double, 2> painted(double lon, double lat) {
  std::array<double, 2> p{lon, lat};
  for (int k = 0; k < 50; ++k) {
    const auto d = bulge(p[0], p[1]);
    p = {lon + d[0], lat + d[1]};
  }
  return p;
}

constexpr double kEyeLon = 10.15, kEyeLat = 44.975, kEyeHeight = 5000;
const test::TestCamera kCamera{0, -27, 55, 800, 500};
const std::string kTrueCamera =
    " --camera 10.15 44.975 5000 --heading 0 --pitch -27 --fov 55 --size 800 500";

struct Scene {
  std::string dir = test::temp_dir(), store = dir + "/s.mqt", points = dir + "/points.json",
              near_points = dir + "/near.json";
  std::vector<std::array<double, 2>> summits;  // the hills in view: lon, lat
  Scene() {
    // The DEM, and the painted world: the DEM moved by the bulge, h(x - bulge(x)).
    test::RasterSpec spec = test::lonlat_raster(9.95, 45.25, 2000, 0.0002, "Float32");
    spec.height = 1500;
    test::write_raster(dir + "/dem.tif", spec,
                       [](int, double lon, double lat) { return dem_height(lon, lat); });
    test::write_raster(dir + "/painted.tif", spec, [](int, double lon, double lat) {
      const auto d = bulge(lon, lat);
      return dem_height(lon - d[0], lat - d[1]);
    });
    for (const char* layer : {"dem", "painted"}) {
      const auto r =
          run_maquette("ingest " + store + " --layer " + layer +
                       " --as dem --vertical-datum ellipsoid " + dir + "/" + layer + ".tif");
      EXPECT_EQ(r.exit_code, 0) << r.err;
    }
    // Clicks on the ground between the hills, where the painting shows them; those of the nearest
    // rows (south of 45.1) also in a file of their own.
    json all{{"width", kCamera.width}, {"height", kCamera.height}, {"points", json::array()}};
    json near = all;
    for (int i = 0; i <= kHillsEast; ++i)
      for (int j = 0; j <= kHillsNorth; ++j) {
        const double lon = kHillLon0 + kHillDLon * (i - 0.5),
                     lat = kHillLat0 + kHillDLat * (j - 0.5);
        const auto pixel = painting_pixel(lon, lat, dem_height(lon, lat));
        if (!pixel) continue;
        const json click{{"x", (*pixel)[0]},
                         {"y", (*pixel)[1]},
                         {"lon", lon},
                         {"lat", lat},
                         {"height", dem_height(lon, lat)}};
        all["points"].push_back(click);
        if (lat < 45.1) near["points"].push_back(click);
      }
    std::ofstream(points) << all.dump();
    std::ofstream(near_points) << near.dump();
    for (int i = 0; i < kHillsEast; ++i)
      for (int j = 0; j < kHillsNorth; ++j) {
        const double lon = kHillLon0 + kHillDLon * i, lat = kHillLat0 + kHillDLat * j;
        const auto pixel = painting_pixel(lon, lat, dem_height(lon, lat));
        if (pixel && (*pixel)[0] > 20 && (*pixel)[0] < 780 && (*pixel)[1] > 20 && (*pixel)[1] < 480)
          summits.push_back({lon, lat});
      }
  }
  // Where the painting shows the DEM's point: its painted place under the true camera (picture
  // coordinates); nothing outside the painting.
  static std::optional<std::array<double, 2>> painting_pixel(double lon, double lat, double h) {
    static const test::ProjEnu enu(kEyeLon, kEyeLat, kEyeHeight);
    const auto p = painted(lon, lat);
    const auto px = kCamera.project(enu({p[0], p[1]}, h));
    const double x = px[0] + 0.5, y = px[1] + 0.5;
    if (x < 0 || y < 0 || x > kCamera.width || y > kCamera.height) return std::nullopt;
    return std::array<double, 2>{x, y};
  }
};

const Scene& scene() {
  static const Scene s;
  return s;
}

json read_json(const std::string& path) {
  std::ifstream in(path);
  return json::parse(in);
}

// The altitude guide of a panorama.
struct Altitudes {
  int width = 0, height = 0;
  std::vector<double> values;
  explicit Altitudes(const std::string& guides) {
    std::unique_ptr<GDALDataset> ds(GDALDataset::Open(guides.c_str(), GDAL_OF_RASTER));
    EXPECT_TRUE(ds) << guides;
    if (!ds) return;
    width = ds->GetRasterXSize();
    height = ds->GetRasterYSize();
    values.resize(size_t(width) * size_t(height));
    EXPECT_EQ(ds->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, width, height, values.data(), width,
                                             height, GDT_Float64, 0, 0),
              CE_None);
  }
  // A summit's place in the picture: the centroid of the pixels within 3 m of the highest
  // altitude within `reach` pixels of `near`.
  std::array<double, 2> summit(const std::array<double, 2>& near, int reach) const {
    const int x0 = std::max(0, int(near[0]) - reach),
              x1 = std::min(width - 1, int(near[0]) + reach),
              y0 = std::max(0, int(near[1]) - reach),
              y1 = std::min(height - 1, int(near[1]) + reach);
    double top = -1e9;
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x)
        if (std::isfinite(at(x, y))) top = std::max(top, at(x, y));
    double sx = 0, sy = 0, n = 0;
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x)
        if (at(x, y) >= top - 3) sx += x + 0.5, sy += y + 0.5, ++n;
    return {sx / n, sy / n};
  }
  double at(int x, int y) const { return values[size_t(y) * size_t(width) + size_t(x)]; }
};

// The fitted camera as the tests' pinhole and frame: where it draws (lon, lat, h).
std::array<double, 2> fitted_pixel(const json& fit, double lon, double lat, double h) {
  const json& c = fit.at("camera");
  const test::ProjEnu enu(c.at("eye")[0], c.at("eye")[1], c.at("eye")[2]);
  const test::TestCamera camera{c.at("heading"), c.at("pitch"), c.at("fov"), kCamera.width,
                                kCamera.height};
  const auto px = camera.project(enu({lon, lat}, h));
  return {px[0] + 0.5, px[1] + 0.5};
}

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
  return v[v.size() / 2];
}

TEST(WarpedDemCli, SummitsLandWhereThePaintingHasThem) {
  const Scene& s = scene();
  ASSERT_GE(s.summits.size(), 10u);
  const std::string out = s.dir + "/fit.json";
  const auto r = run_maquette("render fit " + s.store + " " + s.points + " " + out +
                              " --dem dem --warp-smoothing 0 --warped-dem warped");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json fit = read_json(out);
  const std::string options = fit.at("render_options");
  for (const std::string& run : {"painted" + kTrueCamera, "warped " + options, "dem " + options}) {
    const std::string name = run.substr(0, run.find(' '));
    const auto p =
        run_maquette("render panorama " + s.store + " " + s.dir + "/" + name + ".png --dem " + run);
    ASSERT_EQ(p.exit_code, 0) << p.err;
  }
  const Altitudes painting(s.dir + "/painted-guides.tif"), warped(s.dir + "/warped-guides.tif"),
      plain(s.dir + "/dem-guides.tif");
  // The nearest row of hills lies below every click in the picture: the spline extrapolates
  // there, and its errors are told apart.
  std::vector<double> warped_errors, plain_errors, nearest_row;
  for (const auto& [lon, lat] : s.summits) {
    const double h = dem_height(lon, lat);
    const auto expected = *Scene::painting_pixel(lon, lat, h);
    const auto truth = painting.summit(expected, 12);
    const auto w = warped.summit(expected, 12);
    const auto p = plain.summit(fitted_pixel(fit, lon, lat, h), 12);
    (lat == kHillLat0 ? nearest_row : warped_errors)
        .push_back(std::hypot(w[0] - truth[0], w[1] - truth[1]));
    if (lat != kHillLat0) plain_errors.push_back(std::hypot(p[0] - truth[0], p[1] - truth[1]));
  }
  const double worst = *std::max_element(warped_errors.begin(), warped_errors.end()),
               worst_plain = *std::max_element(plain_errors.begin(), plain_errors.end());
  std::printf(
      "%zu held-out summits among the clicks: warped DEM %.2f px median, %.2f px worst; the DEM as "
      "it was %.2f px median, %.2f px worst; %zu of the nearest row, below the clicks: %.2f px "
      "worst\n",
      warped_errors.size(), median(warped_errors), worst, median(plain_errors), worst_plain,
      nearest_row.size(), *std::max_element(nearest_row.begin(), nearest_row.end()));
  EXPECT_LE(median(warped_errors), 1.0);
  EXPECT_LE(worst, 2.0);
  EXPECT_GT(worst_plain, 5.0);
  for (const json& p : fit.at("points")) EXPECT_EQ(p.at("ground_move").size(), 2u) << p;
}

// The warped layer through GDAL (`export gtiff` in the grid's plane, tiles written exactly), the
// clicks of the nearest rows only (some 3 km apart: the warp fades out within some 7 km): the
// DEM's georeferencing, and its bits wherever the clicks are far (beyond 12 km of each); moved
// near them; the same bits when written again.
TEST(WarpedDemCli, FarFromTheClicksTheDemIsKeptBitForBit) {
  const Scene& s = scene();
  for (const char* layer : {"far", "again"}) {
    const auto r =
        run_maquette("render fit " + s.store + " " + s.near_points + " " + s.dir + "/" + layer +
                     ".json --dem dem --warp-smoothing 0.001 --warped-dem " + layer);
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  for (const char* layer : {"dem", "far", "again"}) {
    const auto e = run_maquette("export gtiff " + s.store + " " + s.dir + "/" + layer +
                                "-export.tif --layer " + layer + " --crs rhealpix");
    ASSERT_EQ(e.exit_code, 0) << e.err;
  }
  std::unique_ptr<GDALDataset> dem(
      GDALDataset::Open((s.dir + "/dem-export.tif").c_str(), GDAL_OF_RASTER));
  std::unique_ptr<GDALDataset> far(
      GDALDataset::Open((s.dir + "/far-export.tif").c_str(), GDAL_OF_RASTER));
  ASSERT_TRUE(dem && far);
  const int w = dem->GetRasterXSize(), h = dem->GetRasterYSize();
  ASSERT_EQ(far->GetRasterXSize(), w);
  ASSERT_EQ(far->GetRasterYSize(), h);
  double a[6], b[6];
  ASSERT_EQ(dem->GetGeoTransform(a), CE_None);
  ASSERT_EQ(far->GetGeoTransform(b), CE_None);
  for (int k = 0; k < 6; ++k) EXPECT_EQ(a[k], b[k]);
  std::vector<float> before(size_t(w) * size_t(h)), after(before.size());
  ASSERT_EQ(
      dem->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, w, h, before.data(), w, h, GDT_Float32, 0, 0),
      CE_None);
  ASSERT_EQ(
      far->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, w, h, after.data(), w, h, GDT_Float32, 0, 0),
      CE_None);
  // Each pixel's lon/lat, through the export's own CRS, to tell how far it is from the clicks.
  const char* wkt = dem->GetProjectionRef();
  OGRSpatialReference plane(wkt), lonlat;
  lonlat.SetWellKnownGeogCS("WGS84");
  lonlat.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  std::unique_ptr<OGRCoordinateTransformation> to_lonlat(
      OGRCreateCoordinateTransformation(&plane, &lonlat));
  ASSERT_TRUE(to_lonlat);
  const json points = read_json(s.near_points).at("points");
  int64_t far_pixels = 0, kept = 0, moved = 0;
  for (int y = 0; y < h; y += 3)
    for (int x = 0; x < w; x += 3) {
      double px = a[0] + (x + 0.5) * a[1], py = a[3] + (y + 0.5) * a[5];
      ASSERT_TRUE(to_lonlat->Transform(1, &px, &py));
      double nearest = 1e12;
      for (const json& p : points)
        nearest = std::min(nearest, std::hypot((px - p.at("lon").get<double>()) * 78700,
                                               (py - p.at("lat").get<double>()) * 111320));
      const size_t i = size_t(y) * size_t(w) + size_t(x);
      if (std::isnan(before[i])) continue;
      if (nearest > 12000) {
        ++far_pixels;
        kept += std::memcmp(&before[i], &after[i], sizeof(float)) == 0;
      } else {
        moved += before[i] != after[i];
      }
    }
  // Deterministic: the same layer again.
  std::unique_ptr<GDALDataset> again(
      GDALDataset::Open((s.dir + "/again-export.tif").c_str(), GDAL_OF_RASTER));
  ASSERT_TRUE(again);
  std::vector<float> same(before.size());
  ASSERT_EQ(
      again->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, w, h, same.data(), w, h, GDT_Float32, 0, 0),
      CE_None);
  EXPECT_EQ(std::memcmp(same.data(), after.data(), after.size() * sizeof(float)), 0);
  std::printf("%lld pixels (1 in 9) beyond 12 km of the clicks, %lld the same bits; %lld moved\n",
              (long long)far_pixels, (long long)kept, (long long)moved);
  EXPECT_GT(far_pixels, 10000);
  EXPECT_EQ(kept, far_pixels);
  EXPECT_GT(moved, 1000);
}

void expect_error(const std::string& args, const std::string& message) {
  const auto r = run_maquette(args);
  EXPECT_NE(r.exit_code, 0) << args;
  EXPECT_NE(r.err.find(message), std::string::npos) << args << "\n" << r.err;
}

TEST(WarpedDemCli, BadNamesAndInputWriteNothing) {
  const Scene& s = scene();
  const std::string out = s.dir + "/bad.json",
                    fit = "render fit " + s.store + " " + s.points + " " + out + " --dem dem ";
  expect_error(fit + "--warp-smoothing 0 --warped-dem dem",
               "--warped-dem layer 'dem' already exists in " + s.store);
  expect_error(fit + "--warp-smoothing 0 --warped-dem painted",
               "--warped-dem layer 'painted' already exists");
  expect_error(fit + "--warp-smoothing 0 --warped-dem ''",
               "--warped-dem: the layer's name is empty");
  expect_error(fit + "--warped-dem w", "--warped-dem requires --warp-smoothing");
  // A bad --panorama layer, found after the fit: no layer, no JSON.
  expect_error(
      fit + "--warp-smoothing 0 --warped-dem w --panorama " + s.dir + "/bad.png --land-cover dem",
      "--land-cover layer 'dem' is not categorical");
  EXPECT_FALSE(std::ifstream(out));
  EXPECT_FALSE(std::ifstream(s.dir + "/bad.png"));
  const auto info = run_maquette("info " + s.store);
  EXPECT_EQ(info.out.find("\n  w: "), std::string::npos) << info.out;
}

// A warped DEM that an interrupted run left incomplete (made here as that run would leave it) is
// written again; once whole, its name is refused like any other.
TEST(WarpedDemCli, AnInterruptedLayerIsWrittenAgain) {
  const Scene& s = scene();
  CellId stale;
  {
    const auto store = Store::open(s.store, Store::Mode::ReadWrite);
    LayerInfo layer = *store->layer("dem");
    layer.name = "cut";
    layer.provenance = {{"warped_by", {{"command", "render fit"}}}};
    store->create_layer(layer);
    store->mark_incomplete("cut", store->begin_run({{"render fit --warped-dem", "cut short"}}));
    // A tile the interrupted run wrote of a cell the new run does not write (another DEM's, say):
    // it must not survive into the new layer.
    const CellId first = store->tile_cells("dem").front();
    stale = CellId::FromFaceColRow(first.face() == 0 ? 5 : 0, first.level(), 0, 0);
    store->put_tile("cut", stale, *store->get_tile("dem", first));
  }
  const std::string fit = "render fit " + s.store + " " + s.near_points + " " + s.dir +
                          "/cut.json --dem dem --warp-smoothing 0 --warped-dem cut";
  const auto r = run_maquette(fit);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto store = Store::open(s.store, Store::Mode::ReadOnly);
  EXPECT_FALSE(store->incomplete("cut"));
  EXPECT_EQ(store->stats("cut").tile_count, store->stats("dem").tile_count);
  EXPECT_FALSE(store->get_tile("cut", stale)) << "the interrupted run's tile survived";
  expect_error(fit, "--warped-dem layer 'cut' already exists");
}

}  // namespace
}  // namespace maquette
