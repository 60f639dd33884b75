// `maquette render panorama` on a synthetic DEM (a 600 m plateau on a plain, heights above the
// ellipsoid): every terrain pixel's guides (lon, lat, altitude) name a point that the test's own
// pinhole puts back on that pixel's centre (<= 0.05 px) at the guide's distance (PROJ's
// east-north-up frame, not the program's GeographicLib), the plateau's edge drawn as a
// silhouette, the land-cover guide the class at the guide's lon/lat; --look-at and --above-ground
// aim and place the camera where PROJ says, --exaggeration scales the heights; a bent panorama
// (--bend-radius) puts each guide point where the test's own bend of PROJ's point projects, its
// horizon higher than the unbent one's, an infinite radius the unbent picture bit for bit; terrain
// past the imagery's edge takes the edge's colour within kTextureReach texels, farther grey 128
// (times its shading); the same bytes for 1 and 2 threads, bent or not; bad input named.
#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <numbers>
#include <numeric>
#include <set>
#include <sstream>

#include "core/grid.h"
#include "proj_enu.h"
#include "render/panorama.h"
#include "render/render_job.h"
#include "render/terrain_scene.h"
#include "run_cli.h"
#include "store/store.h"
#include "synthetic_raster.h"
#include "test_camera.h"

namespace maquette {
namespace {

using test::run_maquette;

constexpr double kEyeLon = 10.15, kEyeLat = 45.02, kEyeHeight = 1500;

bool on_plateau(double lon, double lat) {
  return lon > 10.12 && lon < 10.18 && lat > 45.12 && lat < 45.18;
}

// Forest (41) on the plateau, shrub (52) around it.
int land_cover(double lon, double lat) { return on_plateau(lon, lat) ? 41 : 52; }

struct Fixture {
  std::string dir = test::temp_dir(), store = dir + "/s.mqt";
  Fixture() {
    const std::string tif = dir + "/dem.tif";
    test::write_raster(
        tif, test::lonlat_raster(10, 45.3, 600, 0.0005, "Float32"),
        [](int, double lon, double lat) { return on_plateau(lon, lat) ? 700 : 100; });
    const auto r = run_maquette("ingest " + store + " --layer dem --as dem --vertical-datum " +
                                "ellipsoid " + tif);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    const std::string classes = dir + "/classes.tif";
    test::write_raster(classes, test::lonlat_raster(10, 45.3, 600, 0.0005, "Byte"),
                       [](int, double lon, double lat) { return land_cover(lon, lat); });
    const auto c = run_maquette("ingest " + store + " --layer lc --as landcover " + classes);
    EXPECT_EQ(c.exit_code, 0) << c.err;
  }
  std::string render(const std::string& out, const std::string& options) const {
    return "render panorama " + store + " " + out + " --dem dem --camera " +
           std::to_string(kEyeLon) + " " + std::to_string(kEyeLat) + " " +
           std::to_string(kEyeHeight) + " " + options;
  }
};

const Fixture& fixture() {
  static const Fixture f;
  return f;
}

const char* kView = "--heading 0 --pitch -6 --fov 50 --size 320 200";

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<double> band(GDALDataset& ds, int b) {
  std::vector<double> v(size_t(ds.GetRasterXSize()) * size_t(ds.GetRasterYSize()));
  EXPECT_EQ(ds.GetRasterBand(b)->RasterIO(GF_Read, 0, 0, ds.GetRasterXSize(), ds.GetRasterYSize(),
                                          v.data(), ds.GetRasterXSize(), ds.GetRasterYSize(),
                                          GDT_Float64, 0, 0),
            CE_None);
  return v;
}

using Enu = std::array<double, 3>;

// The guides of `path` (bands altitude, distance, lon, lat): the largest distance (pixels) from a
// terrain pixel's centre to where `camera`, at the eye, puts the point its guides name (its
// altitude times `exaggeration`: heights here are above the ellipsoid; moved by `bend`), and the
// largest relative error of its distance, both measured in PROJ's east-north-up frame; and the
// number of terrain pixels.
std::array<double, 3> worst_reprojection(
    const std::string& path, const test::TestCamera& camera, double eye_height,
    double exaggeration = 1,
    const std::function<Enu(const Enu&)>& bend = [](const Enu& p) { return p; }) {
  std::unique_ptr<GDALDataset> guides(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER));
  EXPECT_TRUE(guides);
  if (!guides) return {1e9, 1e9, 0};
  const auto altitude = band(*guides, 1), distance = band(*guides, 2), lon = band(*guides, 3),
             lat = band(*guides, 4);
  const test::ProjEnu enu(kEyeLon, kEyeLat, eye_height);
  std::array<double, 3> worst{0, 0, 0};
  for (int row = 0; row < camera.height; ++row)
    for (int col = 0; col < camera.width; ++col) {
      const size_t i = size_t(row) * size_t(camera.width) + size_t(col);
      if (std::isnan(distance[i])) continue;
      ++worst[2];
      const auto p = bend(enu({lon[i], lat[i]}, altitude[i] * exaggeration));
      const auto px = camera.project(p);
      const double range = std::hypot(p[0], p[1], p[2]);
      worst[0] = std::max(worst[0], std::hypot(px[0] - col, px[1] - row));
      worst[1] = std::max(worst[1], std::abs(range - distance[i]) / range);
    }
  return worst;
}

TEST(PanoramaCli, GuidesNameThePointEachPixelShows) {
  const Fixture& f = fixture();
  const std::string out = f.dir + "/pano.png";
  const auto r = run_maquette(f.render(out, std::string(kView) + " --land-cover lc"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  GDALAllRegister();
  std::unique_ptr<GDALDataset> guides(
      GDALDataset::Open((f.dir + "/pano-guides.tif").c_str(), GDAL_OF_RASTER));
  ASSERT_TRUE(guides);
  ASSERT_EQ(guides->GetRasterCount(), 6);
  EXPECT_STREQ(guides->GetRasterBand(2)->GetDescription(), "distance");
  EXPECT_STREQ(guides->GetRasterBand(5)->GetDescription(), "land_cover");
  EXPECT_STREQ(guides->GetRasterBand(6)->GetDescription(), "shading");
  const auto altitude = band(*guides, 1), distance = band(*guides, 2), lon = band(*guides, 3),
             lat = band(*guides, 4), classes = band(*guides, 5);
  std::unique_ptr<GDALDataset> edges(
      GDALDataset::Open((f.dir + "/pano-silhouettes.png").c_str(), GDAL_OF_RASTER));
  ASSERT_TRUE(edges);
  std::vector<uint8_t> silhouette(altitude.size());
  ASSERT_EQ(edges->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, 320, 200, silhouette.data(), 320, 200,
                                              GDT_Byte, 0, 0),
            CE_None);

  const auto [worst_pixel, worst_distance, seen] =
      worst_reprojection(f.dir + "/pano-guides.tif", {0, -6, 50, 320, 200}, kEyeHeight);
  EXPECT_LE(worst_pixel, 0.05);  // the guide point lies on the ray through the pixel centre
  EXPECT_LE(worst_distance, 1e-4);
  size_t terrain = 0, plateau = 0, plateau_edges = 0, sky = 0, same_class = 0, away_from_edge = 0;
  for (int row = 0; row < 200; ++row)
    for (int col = 0; col < 320; ++col) {
      const size_t i = size_t(row) * 320 + size_t(col);
      if (std::isnan(distance[i])) {
        ++sky;
        continue;
      }
      ++terrain;
      // The class of the nearest sample: either class within two samples of the plateau's edge.
      const double margin = 0.001;
      if (on_plateau(lon[i] - margin, lat[i] - margin) ==
              on_plateau(lon[i] + margin, lat[i] + margin) &&
          on_plateau(lon[i] - margin, lat[i] + margin) ==
              on_plateau(lon[i] + margin, lat[i] - margin)) {
        ++away_from_edge;
        same_class += classes[i] == land_cover(lon[i], lat[i]);
      }
      if (altitude[i] > 650) {
        ++plateau;
        plateau_edges += silhouette[i] == 255;
      }
    }
  EXPECT_EQ(same_class, away_from_edge);
  EXPECT_GT(away_from_edge, terrain * 9 / 10);
  EXPECT_GT(terrain, 320u * 50);  // the plain, the plateau and the sky above the far edge
  EXPECT_EQ(seen, double(terrain));
  EXPECT_GT(sky, 320u * 20);
  EXPECT_GT(plateau, 500u);
  EXPECT_GT(plateau_edges, 20u);  // the plateau's top edge against the plain behind it
}

TEST(PanoramaCli, LookAtAboveGroundAimsTheCamera) {
  // 1400 m above the plain (100 m) is the eye of the other tests; aimed at the plateau's centre,
  // whose direction PROJ gives here.
  const Fixture& f = fixture();
  const std::string out = f.dir + "/aimed.png";
  const auto r =
      run_maquette("render panorama " + f.store + " " + out + " --dem dem --camera " +
                   std::to_string(kEyeLon) + " " + std::to_string(kEyeLat) +
                   " 1400 --above-ground --look-at 10.15 45.15 700 --fov 40 --size " + "321 201");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto target = test::ProjEnu(kEyeLon, kEyeLat, kEyeHeight)({10.15, 45.15}, 700);
  const double heading = std::atan2(target[0], target[1]) * 180 / std::numbers::pi;
  const double pitch =
      std::atan2(target[2], std::hypot(target[0], target[1])) * 180 / std::numbers::pi;
  const auto [worst_pixel, worst_distance, seen] =
      worst_reprojection(f.dir + "/aimed-guides.tif", {heading, pitch, 40, 321, 201}, kEyeHeight);
  EXPECT_LE(worst_pixel, 0.05);
  EXPECT_LE(worst_distance, 1e-4);
  EXPECT_GT(seen, 321 * 201 / 2);  // looking down at the plateau: mostly terrain
}

TEST(PanoramaCli, ExaggeratedHeights) {
  const Fixture& f = fixture();
  const std::string out = f.dir + "/tall.png";
  const auto r = run_maquette(f.render(out, std::string(kView) + " --exaggeration 1.8"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto [worst_pixel, worst_distance, seen] =
      worst_reprojection(f.dir + "/tall-guides.tif", {0, -6, 50, 320, 200}, kEyeHeight, 1.8);
  EXPECT_LE(worst_pixel, 0.05);
  EXPECT_LE(worst_distance, 1e-4);
  EXPECT_GT(seen, 320 * 50);
  // Without the exaggeration the same guides miss their pixels.
  EXPECT_GT(worst_reprojection(f.dir + "/tall-guides.tif", {0, -6, 50, 320, 200}, kEyeHeight)[0],
            5.0);

  // The eye stands above the ground as drawn: 100 m over the plain drawn at 2 x 100 m, so
  // straight down the distance is 100 m; an eye at 150 m is under the drawn plain: refused.
  const std::string eye =
      " --dem dem --camera " + std::to_string(kEyeLon) + " " + std::to_string(kEyeLat) + " ";
  const auto above =
      run_maquette("render panorama " + f.store + " " + f.dir + "/down.png" + eye +
                   "100 --above-ground --exaggeration 2 --pitch -90 --fov 10 " + "--size 21 21");
  ASSERT_EQ(above.exit_code, 0) << above.err;
  std::unique_ptr<GDALDataset> down(
      GDALDataset::Open((f.dir + "/down-guides.tif").c_str(), GDAL_OF_RASTER));
  ASSERT_TRUE(down);
  EXPECT_NEAR(band(*down, 2)[10 * 21 + 10], 100, 0.01);
  const auto under = run_maquette("render panorama " + f.store + " " + f.dir + "/under.png" + eye +
                                  "150 --exaggeration 2");
  EXPECT_NE(under.exit_code, 0);
  EXPECT_NE(under.err.find("below the terrain"), std::string::npos) << under.err;
}

TEST(PanoramaCli, SameBytesForOneAndTwoThreads) {
  const Fixture& f = fixture();
  const std::string one = f.dir + "/one.png", two = f.dir + "/two.png";
  ASSERT_EQ(run_maquette(f.render(one, std::string(kView) + " -t 1")).exit_code, 0);
  ASSERT_EQ(run_maquette(f.render(two, std::string(kView) + " -t 2")).exit_code, 0);
  EXPECT_EQ(slurp(one), slurp(two));
  EXPECT_EQ(slurp(f.dir + "/one-guides.tif"), slurp(f.dir + "/two-guides.tif"));
  EXPECT_EQ(slurp(f.dir + "/one-silhouettes.png"), slurp(f.dir + "/two-silhouettes.png"));
  EXPECT_GT(slurp(one).size(), 1000u);
}

// The first terrain row from the top in each column of a panorama's distance guide.
std::vector<int> horizon(const std::string& guides_path, int width, int height) {
  std::unique_ptr<GDALDataset> guides(GDALDataset::Open(guides_path.c_str(), GDAL_OF_RASTER));
  EXPECT_TRUE(guides);
  if (!guides) return {};
  const auto distance = band(*guides, 2);
  std::vector<int> rows(size_t(width), height);
  for (int col = 0; col < width; ++col)
    for (int row = height - 1; row >= 0; --row)
      if (!std::isnan(distance[size_t(row) * size_t(width) + size_t(col)])) rows[size_t(col)] = row;
  return rows;
}

TEST(PanoramaCli, BentPanorama) {
  const Fixture& f = fixture();
  const double radius = 40000, start = 3000;
  const std::string bend =
      " --bend-radius " + std::to_string(radius) + " --bend-start " + std::to_string(start);
  const std::string bent = f.dir + "/bent.png", two = f.dir + "/bent2.png";
  ASSERT_EQ(run_maquette(f.render(bent, std::string(kView) + bend + " -t 1")).exit_code, 0);
  ASSERT_EQ(run_maquette(f.render(two, std::string(kView) + bend + " -t 2")).exit_code, 0);
  EXPECT_EQ(slurp(bent), slurp(two));
  EXPECT_EQ(slurp(f.dir + "/bent-guides.tif"), slurp(f.dir + "/bent2-guides.tif"));
  EXPECT_EQ(slurp(f.dir + "/bent-silhouettes.png"), slurp(f.dir + "/bent2-silhouettes.png"));

  // The test's own bend: beyond the start, the vertical section through the eye rotated by
  // (d - start) / radius about the axis `radius` above the ground under the eye (the plain, 100 m
  // above the ellipsoid), seen from the tangent point's vertical.
  const double base = 100 - kEyeHeight;
  const auto bent_point = [&](const Enu& p) {
    const double d = std::hypot(p[0], p[1]);
    if (d <= start) return p;
    const double angle = (d - start) / radius, below = p[2] - (base + radius);
    const double s = start - below * std::sin(angle);
    const double up = base + radius + below * std::cos(angle);
    return Enu{p[0] / d * s, p[1] / d * s, up};
  };
  const auto [worst_pixel, worst_distance, seen] = worst_reprojection(
      f.dir + "/bent-guides.tif", {0, -6, 50, 320, 200}, kEyeHeight, 1, bent_point);
  EXPECT_LE(worst_pixel, 0.05);
  EXPECT_LE(worst_distance, 1e-4);
  // Without the bend the same guides miss their pixels.
  EXPECT_GT(worst_reprojection(f.dir + "/bent-guides.tif", {0, -6, 50, 320, 200}, kEyeHeight)[0],
            5.0);

  // The horizon rises: in no column lower than the unbent picture's, well higher on the whole.
  const std::string flat = f.dir + "/flat.png";
  ASSERT_EQ(run_maquette(f.render(flat, kView)).exit_code, 0);
  const auto flat_rows = horizon(f.dir + "/flat-guides.tif", 320, 200),
             bent_rows = horizon(f.dir + "/bent-guides.tif", 320, 200);
  ASSERT_EQ(flat_rows.size(), bent_rows.size());
  double rise = 0;
  for (size_t c = 0; c < flat_rows.size(); ++c) {
    EXPECT_LE(bent_rows[c], flat_rows[c]) << c;
    rise += double(flat_rows[c] - bent_rows[c]) / double(flat_rows.size());
  }
  EXPECT_GT(rise, 10);

  // An infinite radius is no bend: the unbent files, bit for bit.
  const std::string infinite = f.dir + "/infinite.png";
  ASSERT_EQ(run_maquette(f.render(infinite,
                                  std::string(kView) + " --bend-radius inf " + "--bend-start 3000"))
                .exit_code,
            0);
  EXPECT_EQ(slurp(infinite), slurp(flat));
  EXPECT_EQ(slurp(f.dir + "/infinite-guides.tif"), slurp(f.dir + "/flat-guides.tif"));
  EXPECT_NE(slurp(bent), slurp(flat));
}

// The export step `panorama` through `maquette run`: the command's files, byte for byte, for the
// same options (bent, aimed with look_at, land cover); bad params named.
TEST(PanoramaCli, ExportStepWritesTheCommandsFiles) {
  const Fixture& f = fixture();
  const std::string options =
      "--look-at 10.15 45.15 700 --fov 40 --size 240 150 --exaggeration 1.5 --bend-radius 40000 "
      "--bend-start 2000 --haze-distance 30000 --sun 200 30 --shadows --land-cover lc "
      "--smooth-land-cover --no-stretch --antialias 2";
  ASSERT_EQ(run_maquette(f.render(f.dir + "/cmd.png", options)).exit_code, 0);
  auto pipeline = [&](const std::string& params) {
    std::ofstream(f.dir + "/pipeline.json")
        << R"({"store": "s.mqt", "region": {"bbox": [10, 45, 10.3, 45.3]}, "level": 9,
              "steps": [{"op": "export", "params": {"format": "panorama", "out": "step/pano.png",
              "dem": "dem", "camera": [10.15, 45.02, 1500], )"
        << params << "}}]}";
    return run_maquette("-q run " + f.dir + "/pipeline.json");
  };
  const auto r = pipeline(
      R"("look_at": [10.15, 45.15, 700], "fov": 40, "size": [240, 150], "exaggeration": 1.5,
         "bend_radius": 40000, "bend_start": 2000, "haze_distance": 30000, "sun": [200, 30],
         "shadows": true, "land_cover": "lc", "smooth_land_cover": true, "stretch": false,
         "antialias": 2)");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(slurp(f.dir + "/step/pano.png"), slurp(f.dir + "/cmd.png"));
  EXPECT_EQ(slurp(f.dir + "/step/pano-guides.tif"), slurp(f.dir + "/cmd-guides.tif"));
  EXPECT_EQ(slurp(f.dir + "/step/pano-silhouettes.png"), slurp(f.dir + "/cmd-silhouettes.png"));
  EXPECT_GT(slurp(f.dir + "/cmd-guides.tif").size(), 1000u);

  auto expect_error = [&](const std::string& params, const std::string& message) {
    const auto bad = pipeline(params);
    EXPECT_NE(bad.exit_code, 0) << params;
    EXPECT_NE(bad.err.find(message), std::string::npos) << params << "\n" << bad.err;
  };
  expect_error(R"("size": [240])", "params.size: expected 2 numbers");
  expect_error(R"("look_at": [10.15, 45.15, 700], "pitch": -5)", "\"look_at\" or");
  expect_error(R"("layer": "dem")", "params.layer: not an option of format panorama");
  expect_error(R"("fov": 175)", "camera fov 175");
  expect_error(R"("bend_start": 2000)", "params.bend_start is given without params.bend_radius");
  expect_error(R"("antialias": 9)", "antialias");
  expect_error(R"("smooth_land_cover": true)",
               "params.smooth_land_cover is given without params.land_cover: it smooths nothing");
  // Told when the pipeline is planned, before the steps before it run (it failed after them).
  std::ofstream(f.dir + "/two_steps.json")
      << R"({"store": "s.mqt", "region": {"bbox": [10, 45, 10.3, 45.3]}, "level": 9,
            "steps": [{"op": "terrain.derive", "inputs": {"dem": "dem"},
                       "outputs": {"slope": "slope_before_panorama"}},
                      {"op": "export", "params": {"format": "panorama", "out": "step/p0.png",
                       "dem": "dem", "camera": [10.15, 45.02, 1500], "fov": 0}}]})";
  const auto planned = run_maquette("-q run " + f.dir + "/two_steps.json");
  EXPECT_NE(planned.exit_code, 0);
  EXPECT_NE(planned.err.find("step 2 (export): camera fov 0"), std::string::npos) << planned.err;
  EXPECT_FALSE(
      Store::open(f.dir + "/s.mqt", Store::Mode::ReadOnly)->layer("slope_before_panorama"));
}

// A new store in `dir` holding steep hills (layer dem, 800 m high, 700 m to 1 km apart) from 10 E
// to 10.3 E and from `north` - 0.3 to `north`, in 64-pixel tiles, so the level by distance mixes
// levels within the view.
std::string hills_dem(const std::string& dir, double north) {
  const std::string tif = dir + "/hills.tif", path = dir + "/hills.mqt";
  test::write_raster(tif, test::lonlat_raster(10, north, 600, 0.0005, "Float32"),
                     [](int, double lon, double lat) {
                       return 900 + 800 * std::sin(lon * 2 * std::numbers::pi / 0.009) *
                                        std::cos(lat * 2 * std::numbers::pi / 0.007);
                     });
  const auto r = run_maquette("-q ingest " + path + " --layer dem --as dem --tile-size 64 " +
                              "--vertical-datum ellipsoid " + tif);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return path;
}

// The hills at 45 N and imagery (layer rgb) of stripes and a gradient.
const std::string& hills_store() {
  static const std::string store = [] {
    const std::string dir = test::temp_dir(), path = hills_dem(dir, 45.3);
    test::RasterSpec rgb = test::lonlat_raster(10, 45.3, 600, 0.0005, "Byte");
    rgb.bands = 3;
    test::write_raster(dir + "/rgb.tif", rgb, [](int band, double lon, double lat) {
      return band == 1 ? 60 + 40 * std::sin(lon * 3000) : band == 2 ? (lat - 45) * 600 : 90;
    });
    const auto t = run_maquette("-q ingest " + path + " --layer rgb --as imagery --tile-size 64 " +
                                dir + "/rgb.tif");
    EXPECT_EQ(t.exit_code, 0) << t.err;
    return path;
  }();
  return store;
}

std::vector<uint8_t> picture(const std::string& path) {
  std::unique_ptr<GDALDataset> ds(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER));
  EXPECT_TRUE(ds);
  if (!ds) return {};
  const int w = ds->GetRasterXSize(), h = ds->GetRasterYSize();
  std::vector<uint8_t> rgb(size_t(w) * size_t(h) * 3);
  EXPECT_EQ(ds->RasterIO(GF_Read, 0, 0, w, h, rgb.data(), w, h, GDT_Byte, 3, nullptr, 3, 3 * w, 1,
                         nullptr),
            CE_None);
  return rgb;
}

// Every band of two guides files the same bits (the files' bytes may differ when drawn in strips);
// `path` with one band more, last, named `extra` when given.
void expect_same_guides(const std::string& path, const std::string& reference,
                        const std::string& what, const std::string& extra = "") {
  std::unique_ptr<GDALDataset> a(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER)),
      e(GDALDataset::Open(reference.c_str(), GDAL_OF_RASTER));
  ASSERT_TRUE(a && e) << what;
  ASSERT_EQ(a->GetRasterCount(), e->GetRasterCount() + !extra.empty()) << what;
  if (!extra.empty()) {
    EXPECT_EQ(a->GetRasterBand(a->GetRasterCount())->GetDescription(), extra) << what;
  }
  for (int b = 1; b <= e->GetRasterCount(); ++b) {
    const auto x = band(*a, b), y = band(*e, b);
    EXPECT_EQ(std::memcmp(x.data(), y.data(), x.size() * sizeof(double)), 0) << what << " " << b;
  }
}

// --smooth-land-cover changes the land_cover guide alone (the picture, silhouettes and every other
// guide the same bytes) and only near the plateau's edge, a staircase of the grid's cells there (a
// polar face's, turned to the meridians): away from it each pixel keeps the class at its lon/lat;
// along it some pixels take the other class. The same bytes on one thread in strips of 13 rows.
TEST(PanoramaCli, SmoothLandCoverRoundsOnlyTheClassesEdges) {
  const Fixture& f = fixture();
  GDALAllRegister();
  // Down on the plateau's south-west corner from 4 km away, a cell of land cover ~8 pixels wide.
  for (const auto& [name, options] :
       {std::pair{"cells", ""},
        {"smooth", " --smooth-land-cover"},
        {"smooth-strips", " --smooth-land-cover -t 1 --strip-rows 13"}}) {
    const auto r = run_maquette("render panorama " + f.store + " " + f.dir + "/" + name +
                                ".png --dem dem --camera 10.11 45.10 4000 --look-at 10.12 45.12 "
                                "700 --fov 20 --size 320 200 --land-cover lc" +
                                options);
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  EXPECT_EQ(slurp(f.dir + "/smooth.png"), slurp(f.dir + "/cells.png"));
  EXPECT_EQ(slurp(f.dir + "/smooth-silhouettes.png"), slurp(f.dir + "/cells-silhouettes.png"));
  expect_same_guides(f.dir + "/smooth-strips-guides.tif", f.dir + "/smooth-guides.tif",
                     "strips of 13 rows, one thread");
  std::unique_ptr<GDALDataset> cells(
      GDALDataset::Open((f.dir + "/cells-guides.tif").c_str(), GDAL_OF_RASTER));
  std::unique_ptr<GDALDataset> smooth(
      GDALDataset::Open((f.dir + "/smooth-guides.tif").c_str(), GDAL_OF_RASTER));
  ASSERT_TRUE(cells && smooth);
  for (const int b : {1, 2, 3, 4, 6}) {
    const auto x = band(*smooth, b), y = band(*cells, b);
    EXPECT_EQ(std::memcmp(x.data(), y.data(), x.size() * sizeof(double)), 0) << b;
  }
  const auto lon = band(*cells, 3), lat = band(*cells, 4), before = band(*cells, 5),
             after = band(*smooth, 5);
  size_t away = 0, kept = 0, changed = 0, changed_near = 0;
  for (size_t i = 0; i < lon.size(); ++i) {
    if (std::isnan(lon[i])) {
      EXPECT_TRUE(std::isnan(after[i])) << i;
      continue;
    }
    EXPECT_TRUE(after[i] == 41 || after[i] == 52) << after[i];
    // Two samples of the land cover (0.0005 degrees) and more from the plateau's edge.
    const double margin = 0.001;
    const bool near = on_plateau(lon[i] - margin, lat[i] - margin) !=
                          on_plateau(lon[i] + margin, lat[i] + margin) ||
                      on_plateau(lon[i] - margin, lat[i] + margin) !=
                          on_plateau(lon[i] + margin, lat[i] - margin);
    if (!near) ++away, kept += after[i] == land_cover(lon[i], lat[i]);
    if (after[i] != before[i]) ++changed, changed_near += near;
  }
  EXPECT_EQ(kept, away);
  EXPECT_GT(away, lon.size() / 2);
  EXPECT_GT(changed, 20u);
  EXPECT_EQ(changed_near, changed);
}

// Imagery over the west half of the DEM only (up to lon 10.15). Terrain within the reach past the
// imagery's edge (kTextureReach texels of its level, measured in the grid's plane from the edge's
// meridian) takes the edge's colour, as if the imagery went on; farther, it is drawn in the middle
// of the display range (128 grey), not in a light earth colour that drew a strip of DEM past the
// imagery's edge as a bright rim on the skyline. Each times its shading guide, with no haze (a huge
// haze distance) and the values as stored (--no-stretch). Without the reach, the pixels within it
// were grey (the strip along Zion's skyline). Stretched, the picture in one strip and in strips
// (the stretch's texels read in two ways) are the same bytes.
TEST(PanoramaCli, TerrainPastTheImageryTakesItsEdgeWithinTheReach) {
  const Fixture& f = fixture();
  const std::string dir = test::temp_dir(), store = dir + "/half.mqt";
  std::filesystem::copy_file(f.store, store);
  test::RasterSpec west = test::lonlat_raster(10, 45.3, 600, 0.0005, "Byte");
  west.width = 300;  // up to lon 10.15
  west.bands = 3;
  // Red a triangle wave along the edge (lat: 30 .. 230 and back every 0.02 degree), green a ramp
  // across it (lon: 40 .. 190 over the 0.004 degree, ~10 texels, before the edge), blue 40: a
  // texel taken a few texels away from the nearest along or across the edge has another colour.
  const double period = 0.02, ramp = 0.004;
  auto colour = [&](double lon, double lat) {
    const double phase = lat / period - std::floor(lat / period);
    return std::array<double, 3>{30 + 200 * std::abs(2 * phase - 1),
                                 40 + 150 * std::clamp((lon - 10.15 + ramp) / ramp, 0.0, 1.0), 40};
  };
  // What a colour may move by over a source pixel and a texel (0.0005 + 0.0005 degree): the
  // resampling to the grid's texels, a texel's centre against the point of the edge beside it.
  const std::array<double, 3> slack{400 / period * 0.001, 150 / ramp * 0.001, 0};
  test::write_raster(dir + "/west.tif", west, [&](int band, double lon, double lat) {
    return colour(lon, lat)[size_t(band - 1)];
  });
  const auto t =
      run_maquette("-q ingest " + store + " --layer rgb --as imagery " + dir + "/west.tif");
  ASSERT_EQ(t.exit_code, 0) << t.err;
  const std::string out = dir + "/half.png";
  auto render = [&](const std::string& name, const std::string& options) {
    return run_maquette("render panorama " + store + " " + dir + "/" + name + ".png" +
                        " --dem dem --texture rgb --no-stretch --haze-distance 1e15 " +
                        "--camera 10.15 45.02 1500 " + kView + " " + options);
  };
  const auto r = render("half", "-t 2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // The edge's texels give the same bits on any thread count and strip size.
  for (const char* options : {"-t 1", "--strip-rows 13"}) {
    const std::string name = std::string("half") + (options[1] == 't' ? "1" : "13");
    ASSERT_EQ(render(name, options).exit_code, 0) << options;
    for (const char* file : {".png", "-silhouettes.png"})
      EXPECT_TRUE(slurp(dir + "/" + name + file) == slurp(dir + "/half" + file))
          << options << " " << file;
    expect_same_guides(dir + "/" + name + "-guides.tif", dir + "/half-guides.tif", options);
  }
  // Stretched, over the imagery's own texels only: the picture in one strip (its stretch read from
  // its texels in place, those past the edge left out) is the picture in strips (the texels
  // gathered before the edge's are made), byte for byte.
  for (const char* name : {"stretched", "stretched13"}) {
    const auto s =
        run_maquette("render panorama " + store + " " + dir + "/" + name +
                     ".png --dem dem --texture rgb --haze-distance 1e15 --camera " +
                     "10.15 45.02 1500 " + kView + (name[9] == '1' ? " --strip-rows 13" : ""));
    ASSERT_EQ(s.exit_code, 0) << s.err;
  }
  EXPECT_TRUE(slurp(dir + "/stretched13.png") == slurp(dir + "/stretched.png"));
  EXPECT_FALSE(slurp(dir + "/stretched.png") == slurp(out));  // stretched indeed
  std::unique_ptr<GDALDataset> guides(
      GDALDataset::Open((dir + "/half-guides.tif").c_str(), GDAL_OF_RASTER));
  ASSERT_TRUE(guides);
  const auto lon = band(*guides, 3), lat = band(*guides, 4);
  const auto shading = band(*guides, guides->GetRasterCount());
  const std::vector<uint8_t> rgb = picture(out);
  ASSERT_EQ(rgb.size(), lon.size() * 3);
  const Grid& grid = default_grid();
  const LayerInfo layer = Store::open(store, Store::Mode::ReadOnly)->require_layer("rgb");
  const double texel_m =
      grid.level_info(layer.level, layer.tile_size).plane_side_m / layer.tile_size;
  // The edge's meridian in the plane every 0.0001 degree of lat (11 m, a third of a texel) from
  // lat 45 to 45.3; a pixel's distance from it over 0.03 degree (3 km, ~90 texels) either side.
  std::vector<PlanePoint> edge;
  for (int j = 0; j <= 3000; ++j) edge.push_back(grid.forward({10.15, 45.0 + j * 0.0001}));
  size_t textured = 0, reached = 0, bare = 0;
  double worst = 0;
  for (size_t i = 0; i < lon.size(); ++i) {
    if (std::isnan(lon[i])) continue;  // sky
    const PlanePoint q = grid.forward({lon[i], lat[i]});
    const int j = int((lat[i] - 45.0) / 0.0001);
    double d = INFINITY;  // texels from the edge
    int nearest = 0;      // the edge's point nearest the pixel's
    for (int k = std::max(0, j - 300); k <= std::min(3000, j + 300); ++k) {
      const double dk = std::hypot(q.x - edge[size_t(k)].x, q.y - edge[size_t(k)].y) / texel_m;
      if (dk < d) d = dk, nearest = k;
    }
    const bool past = lon[i] > 10.15;
    if (d < 2 || (past && std::abs(d - kTextureReach) < 2))
      continue;  // the edge's texels (half a texel either side), the reach's rim
    const bool coloured = !past || d < kTextureReach;
    ++(!past ? textured : coloured ? reached : bare);
    const auto expected = !past      ? colour(lon[i], lat[i])
                          : coloured ? colour(10.15, 45.0 + nearest * 0.0001)
                                     : std::array<double, 3>{128, 128, 128};
    for (size_t k = 0; k < 3; ++k)
      worst = std::max(
          worst, std::abs(rgb[3 * i + k] - expected[k] * shading[i]) - (coloured ? slack[k] : 0));
  }
  EXPECT_LE(worst, 0.5 + 1e-6);  // rounding and the slack alone
  EXPECT_GT(textured, 5000u);
  EXPECT_GT(reached, 500u);
  EXPECT_GT(bare, 5000u);
}

// A sample on a tile's border is drawn by both tiles (the halo's ring overlaps the neighbour):
// both copies carry one normal (central differences in each tile, from a second ring of halo),
// so the hillshade shows no line along tile borders. Copies are the vertices within a hundredth
// of a sample of each other (the inside's places are interpolated, the ring's exact: they differ
// by up to a thousandth of a sample, sample_places.h). Before, the ring's normals were one-sided:
// on these hills copies were up to ~60 degrees apart.
// The terrain of `store`'s layer dem seen by `camera` (build_terrain_scene's exaggeration,
// sample_pixels and cull).
TerrainScene scene_of(const std::string& store, const PinholeCamera& camera, double sample_pixels,
                      bool cull, double exaggeration = 1) {
  const auto opened = Store::open(store, Store::Mode::ReadOnly);
  return build_terrain_scene(*opened, default_grid(), opened->require_layer("dem"), camera,
                             exaggeration, sample_pixels, cull);
}

TerrainScene hills_scene(const PinholeCamera& camera, double sample_pixels, bool cull,
                         double exaggeration = 1) {
  return scene_of(hills_store(), camera, sample_pixels, cull, exaggeration);
}

// A skirt hangs only where a neighbour is drawn at another level (or not at all): along a
// neighbour drawn at the same level the two surfaces overlap by a square, and a skirt there showed
// as a wall under the DEM's edge to an eye outside the data. Seen from 20 km straight down every
// tile is drawn whole: a tile whose eight neighbours are all drawn at its level has a vertex per
// sample of its tile and its halo's ring ((n + 2)^2) and no skirt (4 (n + 1) more vertices before).
TEST(PanoramaCli, NoSkirtAlongANeighbourOfTheSameLevel) {
  CameraSpec spec;
  spec.eye = {10.15, 45.15, 20000};
  spec.pitch = -90;
  const TerrainScene scene = hills_scene(PinholeCamera(spec), 0, false);
  const std::set<CellId> cells(scene.cells.begin(), scene.cells.end());
  const size_t n = size_t(scene.tiles[0].heights.size()), ring = (n + 2) * (n + 2);
  size_t inner = 0;
  for (size_t i = 0; i < scene.cells.size(); ++i) {
    const CellId c = scene.cells[i];
    bool surrounded = true;
    for (int dr = -1; dr <= 1; ++dr)
      for (int dc = -1; dc <= 1; ++dc)
        surrounded = surrounded && cells.count(CellId::FromFaceColRow(c.face(), c.level(),
                                                                      uint32_t(int(c.col()) + dc),
                                                                      uint32_t(int(c.row()) + dr)));
    const size_t end =
        i + 1 < scene.tiles.size() ? scene.tiles[i + 1].first_vertex : scene.slot.size();
    const size_t vertices = end - scene.tiles[i].first_vertex;
    if (!surrounded) continue;
    EXPECT_EQ(vertices, ring) << c.ToText();
    ++inner;
  }
  EXPECT_GT(inner, 0u);
}

TEST(PanoramaCli, TileBordersShareTheirNormals) {
  CameraSpec spec;
  spec.eye = {10.15, 45.15, 20000};
  spec.pitch = -90;
  TerrainScene scene = hills_scene(PinholeCamera(spec), 0, false);
  attribute_vertices(scene, nullptr);
  const double eps = 0.01 * 0.0005;  // a hundredth of the DEM's 0.0005-degree sample
  std::vector<size_t> by_lon(scene.altitude.size());
  std::iota(by_lon.begin(), by_lon.end(), size_t(0));
  std::sort(by_lon.begin(), by_lon.end(),
            [&](size_t a, size_t b) { return scene.lonlat[2 * a] < scene.lonlat[2 * b]; });
  size_t copies = 0;
  double worst = 0;  // degrees between two copies' normals
  for (size_t i = 0; i < by_lon.size(); ++i)
    for (size_t j = i + 1; j < by_lon.size(); ++j) {
      const size_t a = by_lon[i], b = by_lon[j];
      if (scene.lonlat[2 * b] - scene.lonlat[2 * a] > eps) break;
      if (std::abs(scene.lonlat[2 * b + 1] - scene.lonlat[2 * a + 1]) > eps) continue;
      double dot = 0;
      for (size_t k = 0; k < 3; ++k) dot += scene.normals[3 * a + k] * scene.normals[3 * b + k];
      worst = std::max(worst, std::acos(std::min(1.0, dot)) * 180 / std::numbers::pi);
      ++copies;
    }
  std::printf("%zu samples drawn twice, their normals at most %.4f degrees apart\n", copies, worst);
  EXPECT_GT(copies, 1000u);
  EXPECT_LT(worst, 0.05);
}

// attribute_vertices for the vertices a picture shows (strip by strip, as render_strips asks)
// writes them with the same bits as for every vertex at once, and only them, each in a slot of its
// own (as many slots as vertices shown): the attributes are a vertex's own, whichever vertices are
// asked for with it. `camera` 320 x 200 on `store`.
void expect_shown_attributes_are_every_vertexs(const std::string& store,
                                               const PinholeCamera& camera) {
  TerrainScene all = scene_of(store, camera, 1, true), shown = scene_of(store, camera, 1, true);
  attribute_vertices(all, nullptr);
  std::vector<bool> seen(shown.slot.size());
  for (int first = 0; first < 200; first += 70) {  // three strips
    const Fragments f = rasterize(shown.mesh, camera, 1.0, first, 70);
    attribute_vertices(shown, &f);
    for (const uint32_t t : f.triangle)
      if (t != Fragments::kSky)
        for (size_t j = 0; j < 3; ++j) seen[shown.mesh.indices[3 * size_t(t) + j]] = true;
  }
  size_t count = 0;
  std::vector<bool> slot_used(shown.altitude.size());
  for (size_t v = 0; v < seen.size(); ++v) {
    EXPECT_EQ(shown.slot[v] != TerrainScene::kNoSlot, seen[v]) << v;
    if (!seen[v]) continue;
    ++count;
    const size_t s = shown.slot[v], a = all.slot[v];
    ASSERT_LT(s, slot_used.size()) << v;
    EXPECT_FALSE(slot_used[s]) << v;
    slot_used[s] = true;
    EXPECT_EQ(std::memcmp(&shown.lonlat[2 * s], &all.lonlat[2 * a], 2 * sizeof(double)), 0) << v;
    EXPECT_EQ(std::memcmp(&shown.plane[2 * s], &all.plane[2 * a], 2 * sizeof(double)), 0) << v;
    EXPECT_EQ(std::memcmp(&shown.normals[3 * s], &all.normals[3 * a], 3 * sizeof(float)), 0) << v;
    EXPECT_EQ(std::memcmp(&shown.altitude[s], &all.altitude[a], sizeof(float)), 0) << v;
  }
  EXPECT_EQ(shown.altitude.size(), count);  // a slot for each vertex shown, no more
  EXPECT_EQ(all.altitude.size(), seen.size());
  std::printf("%zu of %zu vertices shown\n", count, seen.size());
  EXPECT_GT(count, 1000u);
  EXPECT_LT(count, seen.size());
}

TEST(PanoramaCli, ShownVerticesAttributesAreEveryVertexs) {
  expect_shown_attributes_are_every_vertexs(
      hills_store(), PinholeCamera(CameraSpec{
                         .eye = {10.15, 45.02, 2500}, .pitch = -3, .width = 320, .height = 200}));
}

// The same beyond 80 degrees of latitude, where a tile has no lattice and places a sample exactly
// when asked for (render/sample_places.h): the hills 40 degrees north of the others.
TEST(PanoramaCli, ShownVerticesAttributesAreEveryVertexsNearThePole) {
  const std::string store = hills_dem(test::temp_dir(), 85.3);
  expect_shown_attributes_are_every_vertexs(
      store, PinholeCamera(CameraSpec{
                 .eye = {10.15, 85.02, 2500}, .pitch = -3, .width = 320, .height = 200}));
}

// Each tile at the level its distance needs: fewer triangles, several levels, no hole (no sky
// pixel below a terrain pixel in a column: the terrain is a height field seen from above) and
// the picture close to the full-resolution one.
TEST(PanoramaCli, LevelByDistance) {
  GDALAllRegister();
  const std::string dir = test::temp_dir();
  auto render = [&](const std::string& name, double sample_pixels) {
    const auto r = run_maquette(
        "-v render panorama " + hills_store() + " " + dir + "/" + name +
        ".png --dem dem --camera 10.15 45.02 2500 --heading 0 --pitch -3 --fov 50 --size 320 "
        "200 --sample-pixels " +
        std::to_string(sample_pixels));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    const size_t at = r.err.find("panorama: tiles ");
    EXPECT_NE(at, std::string::npos) << r.err;
    return r.err.substr(at, r.err.find('\n', at) - at);  // "panorama: tiles ...; N triangles"
  };
  auto triangles = [](const std::string& log) {
    const size_t end = log.rfind(" triangles");
    return std::stol(log.substr(log.rfind(' ', end - 1) + 1));
  };
  const std::string full = render("full", 0);
  EXPECT_NE(full.find("tiles 187 at level 12;"), std::string::npos) << full;
  const std::vector<uint8_t> reference = picture(dir + "/full.png");
  ASSERT_EQ(reference.size(), 320u * 200 * 3);
  // Measured: 0.21 (1 px), 1.20 (2 px), 3.12 (4 px) of 255 per channel.
  for (const auto& [sample_pixels, mean_limit] : {std::pair{1.0, 0.3}, {2.0, 1.5}, {4.0, 4.0}}) {
    const std::string name = "lod" + std::to_string(int(sample_pixels));
    const std::string log = render(name, sample_pixels);
    EXPECT_NE(log.find("at level 11"), std::string::npos) << log;
    EXPECT_LT(triangles(log), triangles(full)) << log;
    const std::vector<uint8_t> rgb = picture(dir + "/" + name + ".png");
    ASSERT_EQ(rgb.size(), reference.size());
    double sum = 0;
    for (size_t i = 0; i < rgb.size(); ++i) sum += std::abs(int(rgb[i]) - int(reference[i]));
    EXPECT_LE(sum / double(rgb.size()), mean_limit) << name;
    EXPECT_GT(sum, 0) << name;  // the levels did change the picture

    std::unique_ptr<GDALDataset> guides(
        GDALDataset::Open((dir + "/" + name + "-guides.tif").c_str(), GDAL_OF_RASTER));
    ASSERT_TRUE(guides);
    const auto distance = band(*guides, 2);
    size_t holes = 0, terrain = 0;
    for (int col = 0; col < 320; ++col) {
      bool below_terrain = false;
      for (int row = 0; row < 200; ++row) {
        const bool sky = std::isnan(distance[size_t(row) * 320 + size_t(col)]);
        holes += sky && below_terrain;
        terrain += !sky;
        below_terrain = below_terrain || !sky;
      }
    }
    EXPECT_EQ(holes, 0u) << name;
    EXPECT_GT(terrain, 320u * 100) << name;
  }
}

// A picture drawn in strips of rows (a first pass for the display stretch, a row of margin for
// the silhouettes) has the whole picture's pixels bit for bit: the PNGs byte for byte, the guides'
// values, cast shadows included (their GeoTIFF blocks may be laid out in another order).
// Tiles wholly out of the view are left out (with --sample-pixels > 0 and no bend) without
// changing a pixel: a tiny --sample-pixels (every tile at full resolution, culled) against 0
// (every tile).
TEST(PanoramaCli, TilesOutOfViewLeftOutChangeNoPixel) {
  const std::string dir = test::temp_dir();
  auto render = [&](const std::string& name, const std::string& sample_pixels,
                    const std::string& more = "") {
    const auto r = run_maquette("-v render panorama " + hills_store() + " " + dir + "/" + name +
                                ".png --dem dem --texture rgb --camera 10.15 45.1 3000 --heading "
                                "30 --pitch -10 --fov 40 --size 200 120 --sample-pixels " +
                                sample_pixels + more);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return r.err;
  };
  EXPECT_NE(render("all", "0").find("tiles 187 at level 12;"), std::string::npos);
  const std::string culled = render("culled", "1e-9");
  const size_t at = culled.find("panorama: tiles ");
  ASSERT_NE(at, std::string::npos) << culled;
  EXPECT_LT(std::stoi(culled.substr(at + 16)), 120) << culled;  // tiles left, all at level 12
  EXPECT_NE(culled.find(" at level 12;"), std::string::npos) << culled;
  for (const char* file : {".png", "-guides.tif", "-silhouettes.png"})
    EXPECT_EQ(slurp(dir + "/culled" + file), slurp(dir + "/all" + file)) << file;

  // Shadows are cast by the whole DEM, not only by the tiles in view: a low sun behind the eye
  // throws the hills behind it into the picture, whatever the framing.
  const std::string sun = " --shadows --sun 210 6";
  render("all-shadows", "0", sun);
  render("culled-shadows", "1e-9", sun);
  for (const char* file : {".png", "-guides.tif"})
    EXPECT_TRUE(slurp(dir + "/culled-shadows" + file) == slurp(dir + "/all-shadows" + file))
        << file;
}

// The pixels with terrain in `a`'s picture, and those whose depth, weights or sky differ from
// `b`'s (bit for bit).
std::pair<size_t, size_t> pixels_differ(const PinholeCamera& camera, const TerrainScene& a_scene,
                                        const TerrainScene& b_scene) {
  const Fragments a = rasterize(a_scene.mesh, camera), b = rasterize(b_scene.mesh, camera);
  size_t terrain = 0, differ = 0;
  for (size_t i = 0; i < a.depth.size(); ++i) {
    terrain += a.triangle[i] != Fragments::kSky;
    differ += (a.triangle[i] == Fragments::kSky) != (b.triangle[i] == Fragments::kSky) ||
              std::memcmp(&a.depth[i], &b.depth[i], sizeof(double)) != 0 ||
              std::memcmp(&a.b1[i], &b.b1[i], sizeof(float)) != 0 ||
              std::memcmp(&a.b2[i], &b.b2[i], sizeof(float)) != 0;
  }
  return {terrain, differ};
}

// With the cull, a tile's patches of squares wholly out of the view are left out too (their
// samples no vertices unless a drawn square or the skirt uses them), without changing what any
// pixel sees: against the same tiles drawn whole (the culled scene's cells, each with no more
// vertices than unculled and some with fewer), every pixel's depth and weights the same bits, the
// sky the same pixels. The picture's sides cut through tiles, so patches just inside the view (a
// corner peeking in) sit beside patches just outside it. Cameras: oblique; looking down and
// straight down; from inside the hills looking up; a 160-degree view; exaggerated 4 and 0.3
// times; tiles from coarser levels; a view partly off the store.
TEST(PanoramaCli, PatchesOutOfViewLeftOutChangeNoPixel) {
  struct View {
    CameraSpec spec;
    double exaggeration = 1, sample_pixels = 1e-9;
  };
  auto spec = [](double lon, double lat, double height, double heading, double pitch, double fov,
                 int width, int height_px) {
    return CameraSpec{.eye = {lon, lat, height},
                      .heading = heading,
                      .pitch = pitch,
                      .fov = fov,
                      .width = width,
                      .height = height_px};
  };
  const View views[] = {{spec(10.12, 44.99, 3000, 15, -12, 40, 200, 120)},
                        {spec(10.15, 45.15, 4000, 40, -85, 60, 160, 120)},
                        {spec(10.2, 45.2, 3000, 0, -90, 40, 120, 120)},
                        {spec(10.15, 45.15, 950, 120, 20, 90, 200, 120)},
                        {spec(10.15, 45.1, 2500, 200, -20, 160, 240, 100)},
                        {spec(10.12, 44.99, 6000, 15, -12, 40, 200, 120), 4},
                        {spec(10.12, 44.99, 2000, 15, -12, 40, 200, 120), 0.3},
                        {spec(10.1, 45.0, 5000, 20, -15, 50, 200, 120), 1, 4},
                        {spec(10.02, 45.15, 3000, 300, -20, 60, 200, 120)}};
  for (size_t v = 0; v < std::size(views); ++v) {
    const View& view = views[v];
    const std::string name = "view " + std::to_string(v);
    const PinholeCamera camera(view.spec);
    const TerrainScene culled = hills_scene(camera, view.sample_pixels, true, view.exaggeration),
                       whole = hills_scene(camera, view.sample_pixels, false, view.exaggeration);
    auto vertices = [](const TerrainScene& s, size_t i) {
      const size_t end = i + 1 < s.tiles.size() ? s.tiles[i + 1].first_vertex : s.slot.size();
      return end - s.tiles[i].first_vertex;
    };
    size_t fewer = 0;
    for (size_t i = 0; i < culled.cells.size(); ++i) {
      const auto at = std::find(whole.cells.begin(), whole.cells.end(), culled.cells[i]);
      ASSERT_NE(at, whole.cells.end()) << name;
      const size_t all = vertices(whole, size_t(at - whole.cells.begin()));
      EXPECT_LE(vertices(culled, i), all) << name;
      fewer += vertices(culled, i) < all;
    }
    EXPECT_GT(fewer, 0u) << name;
    // Each vertex left is one of the whole's, at the same place (the skirts as deep), but the
    // skirts' along a neighbour of the same level that the whole draws and the cull left out
    // (wholly out of the view): each such vertex hangs under one of the whole's (across by at
    // most a hundredth of its depth: the skirt follows the ellipsoid's normal, within 0.01 rad of
    // the eye's up within 60 km).
    auto points = [](const TerrainScene& s) {
      std::vector<std::array<double, 3>> p(s.mesh.positions.size() / 3);
      for (size_t v = 0; v < p.size(); ++v) std::copy_n(&s.mesh.positions[3 * v], 3, p[v].begin());
      std::sort(p.begin(), p.end());
      return p;
    };
    const auto left = points(culled), all = points(whole);
    std::vector<std::array<double, 3>> extra;
    std::set_difference(left.begin(), left.end(), all.begin(), all.end(),
                        std::back_inserter(extra));
    EXPECT_LT(extra.size(), left.size() / 10) << name;
    std::map<std::pair<int64_t, int64_t>, std::vector<std::array<double, 3>>> all_by_50m;
    auto bin = [](double m) { return int64_t(std::floor(m / 50)); };
    for (const auto& p : all) all_by_50m[{bin(p[0]), bin(p[1])}].push_back(p);
    size_t hanging = 0;
    for (const auto& e : extra) {
      bool above = false;
      for (int64_t i = -1; i <= 1 && !above; ++i)
        for (int64_t j = -1; j <= 1 && !above; ++j) {
          const auto at = all_by_50m.find({bin(e[0]) + i, bin(e[1]) + j});
          if (at == all_by_50m.end()) continue;
          for (const auto& p : at->second) {
            const double across = 0.01 * (p[2] - e[2]);
            above = above || (p[2] > e[2] + 1 && std::abs(p[0] - e[0]) < across &&
                              std::abs(p[1] - e[1]) < across);
          }
        }
      hanging += above;
    }
    EXPECT_EQ(hanging, extra.size()) << name;
    const auto [terrain, differ] = pixels_differ(camera, culled, whole);
    EXPECT_EQ(differ, 0u) << name;
    EXPECT_GT(terrain, 0u) << name;
  }
}

// Beside a polar face's diagonal (the meridian 0 at 50 N on face N) a row of samples bends on the
// ground by about 50 degrees, so a patch's or group's places leave the hull of its corners' by
// more than a sample: the cull still leaves no pixel out. The camera's left side passes just
// beyond such a group's corner hull (found by a probe of the cull; 40 pixels went missing).
TEST(PanoramaCli, PatchesOutOfViewBesideAPolarDiagonalChangeNoPixel) {
  const std::string dir = test::temp_dir(), tif = dir + "/flat.tif", store = dir + "/flat.mqt";
  test::write_raster(tif, test::lonlat_raster(-0.15, 50.1, 600, 0.0005, "Float32"),
                     [](int, double, double) { return 100; });
  const auto r = run_maquette("-q ingest " + store + " --layer dem --as dem " +
                              "--vertical-datum ellipsoid " + tif);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const PinholeCamera camera(CameraSpec{.eye = {0.035493855, 50.044159694, 400},
                                        .heading = 257.789326,
                                        .pitch = -3,
                                        .fov = 40,
                                        .width = 400,
                                        .height = 240});
  const TerrainScene culled = scene_of(store, camera, 1e-9, true),
                     whole = scene_of(store, camera, 1e-9, false);
  EXPECT_LT(culled.mesh.positions.size(), whole.mesh.positions.size());
  const auto [terrain, differ] = pixels_differ(camera, culled, whole);
  EXPECT_EQ(differ, 0u);
  EXPECT_GT(terrain, 400u * 100);
}

TEST(PanoramaCli, StripsGiveTheWholePicture) {
  GDALAllRegister();
  const std::string dir = test::temp_dir();
  auto render = [&](const std::string& name, const std::string& options) {
    const auto r = run_maquette("-q render panorama " + hills_store() + " " + dir + "/" + name +
                                ".png --dem dem --texture rgb --camera 10.15 45.02 2500 --heading "
                                "10 --pitch -8 --fov 60 --size 300 170 --bend-radius 60000 "
                                "--sample-pixels 3 --shadows --sun 200 25 " +
                                options);
    EXPECT_EQ(r.exit_code, 0) << r.err;
  };
  render("whole", "");
  const std::string whole = slurp(dir + "/whole.png");
  for (const char* rows : {"13", "64", "169"}) {
    const std::string name = std::string("strips") + rows;
    render(name, std::string("--strip-rows ") + rows + (rows[0] == '1' ? " -t 1" : ""));
    EXPECT_EQ(slurp(dir + "/" + name + ".png"), whole) << rows;
    EXPECT_EQ(slurp(dir + "/" + name + "-silhouettes.png"), slurp(dir + "/whole-silhouettes.png"))
        << rows;
    expect_same_guides(dir + "/" + name + "-guides.tif", dir + "/whole-guides.tif", rows);
  }
  // The picture is textured and stretched: its colours are not all the plain earth's.
  EXPECT_GT(whole.size(), 20000u);

  // Anti-aliased: the same in strips and threads; only the colours differ from one sample's.
  render("whole3", "--antialias 3");
  const std::string smooth = slurp(dir + "/whole3.png");
  EXPECT_NE(smooth, whole);
  EXPECT_EQ(slurp(dir + "/whole3-silhouettes.png"), slurp(dir + "/whole-silhouettes.png"));
  expect_same_guides(dir + "/whole3-guides.tif", dir + "/whole-guides.tif", "antialias 3",
                     "coverage");
  for (const char* options : {"--strip-rows 13 -t 1", "--strip-rows 64 -t 2", "-t 1"}) {
    render("strips3", std::string("--antialias 3 ") + options);
    EXPECT_EQ(slurp(dir + "/strips3.png"), smooth) << options;
    expect_same_guides(dir + "/strips3-guides.tif", dir + "/whole3-guides.tif", options);
  }
}

// The picture in memory (render_panorama) drawn in strips of fragments of 8, 13 and 64 rows is
// the one drawn in one strip, bit for bit: colours, silhouettes and every guide.
TEST(PanoramaCli, FragmentStripsGiveTheWholePicture) {
  const auto store = Store::open(hills_store(), Store::Mode::ReadOnly);
  PanoramaJob job;
  job.dem = "dem";
  job.texture = "rgb";
  job.camera = CameraSpec{.eye = {10.15, 45.02, 2500},
                          .heading = 10,
                          .pitch = -8,
                          .fov = 60,
                          .width = 300,
                          .height = 170};
  job.bend.radius = 60000;
  job.sample_pixels = 3;
  job.shadows = true;
  job.sun_azimuth = 200;
  job.sun_altitude = 25;
  job.fragment_rows = 170;
  const Panorama whole = render_panorama(*store, default_grid(), job);
  const auto same = [](const auto& a, const auto& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0;
  };
  for (const int rows : {8, 13, 64}) {
    job.fragment_rows = rows;
    const Panorama strips = render_panorama(*store, default_grid(), job);
    EXPECT_TRUE(same(strips.rgb, whole.rgb)) << rows;
    EXPECT_TRUE(same(strips.silhouette, whole.silhouette)) << rows;
    EXPECT_TRUE(same(strips.distance, whole.distance)) << rows;
    EXPECT_TRUE(same(strips.lon_offset, whole.lon_offset)) << rows;
    EXPECT_TRUE(same(strips.lat_offset, whole.lat_offset)) << rows;
    EXPECT_TRUE(same(strips.altitude, whole.altitude)) << rows;
    EXPECT_TRUE(same(strips.cast_shadow, whole.cast_shadow)) << rows;
    EXPECT_TRUE(same(strips.shading, whole.shading)) << rows;
  }
  // A textured, shadowed picture with terrain and sky.
  EXPECT_GT(std::count_if(whole.distance.begin(), whole.distance.end(),
                          [](float d) { return std::isnan(d); }),
            0);
  EXPECT_GT(std::count_if(whole.cast_shadow.begin(), whole.cast_shadow.end(),
                          [](float s) { return s > 0.5f; }),
            0);
}

TEST(PanoramaCli, BadInputIsNamed) {
  const Fixture& f = fixture();
  const std::string out = f.dir + "/bad.png";
  auto expect_error = [&](const std::string& args, const std::string& message) {
    const auto r = run_maquette(args);
    EXPECT_NE(r.exit_code, 0) << args;
    EXPECT_NE(r.err.find(message), std::string::npos) << args << "\n" << r.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << args;
  };
  expect_error("render panorama " + f.store + " " + out + " --dem nosuch --camera 10.15 45 900",
               "--dem layer 'nosuch' is not in the store");
  expect_error(f.render(out, "--texture dem"), "--texture layer 'dem' is float32");
  expect_error("render panorama " + f.store + " " + out + " --dem dem --camera 10.15 45.15 650",
               "below the terrain there (700.0 m)");
  expect_error(
      "render panorama " + f.store + " " + out + " --dem dem --camera 9 45 100 " + "--above-ground",
      "no data under the camera");
  expect_error("render panorama " + f.store + " " + out +
                   " --dem dem --camera 10.15 45.15 -50 --above-ground",
               "--above-ground: the camera's height -50.0 m must be above the ground");
  expect_error(f.render(out, "--fov 175"), "camera fov 175");
  // A file that cannot be written leaves none of the three (the picture was left).
  std::filesystem::create_directory(f.dir + "/bad-silhouettes.png");
  expect_error(f.render(out, ""), "cannot write " + f.dir + "/bad-silhouettes.png: Is a directory");
  EXPECT_FALSE(std::filesystem::exists(f.dir + "/bad-guides.tif"));
  std::filesystem::remove(f.dir + "/bad-silhouettes.png");
  expect_error(f.render(out, "--size 100000 20"),
               "--size 100000 20: a picture is at most 65536 pixels a side");
  expect_error(f.render(out, "--fov 0"), "out of range");
  expect_error(f.render(out, "--bend-radius -300"), "--bend-radius -300");
  expect_error(f.render(out, "--sample-pixels -1"), "--sample-pixels -1");
  expect_error(f.render(out, "--strip-rows -2"), "--strip-rows -2");
  expect_error(f.render(out, "--antialias 0"), "--antialias 0 must be 1 to 8");
  expect_error(f.render(out, "--antialias 9"), "--antialias 9 must be 1 to 8");
  expect_error(f.render(out, "--size 9000 100 --antialias 8"),
               "--antialias 8 on a picture of 9000 x 100 pixels: its samples would span more "
               "than 65536 pixels");
  expect_error(f.render(out, "--bend-radius 9000 --bend-start -5"), "--bend-start -5");
  expect_error(f.render(out, "--bend-start 5000"), "--bend-start requires --bend-radius");
  expect_error(f.render(out, "--smooth-land-cover"), "--smooth-land-cover requires --land-cover");
  // Land-cover classes drawn as heights of a few metres.
  expect_error("render panorama " + f.store + " " + out + " --dem lc --camera 10.15 45.02 1500",
               "--dem layer 'lc' is categorical (classes, not heights)");
  // Classes drawn as grey levels.
  expect_error(f.render(out, "--texture lc"),
               "--texture layer 'lc' is categorical (classes, not colours): give it as "
               "--land-cover");
  // A camera that sees none of the DEM was told "--dem layer 'dem' holds no tiles", or drew an
  // all-sky picture with exit 0 (the tiles near enough to be kept, or not culled: --shadows).
  const std::string up =
      "render panorama " + f.store + " " + out + " --dem dem --camera 10.15 45.02 12000 --pitch 90";
  expect_error(up, "none of the --dem layer 'dem' (lon ");
  expect_error(up,
               "is in the camera's view (at lon 10.1500, lat 45.0200, 12000.0 m; heading 0, pitch "
               "90, fov 60): aim it at the terrain");
  expect_error(f.render(out, "--pitch 90 --shadows"),
               "the picture shows none of the terrain (the camera at lon 10.1500, lat 45.0200, "
               "1500.0 m; heading 0, pitch 90, fov 60): aimed away");
  expect_error(f.render(out, "--heading nan"), "camera heading nan is not finite");
  expect_error(f.render(out, "--exaggeration inf"),
               "--exaggeration inf must be positive and finite");
  expect_error(f.render(out, "--sun nan 40"), "--sun nan 40 must be finite");
  // Lon and lat swapped, a NaN height or look-at: told as an invalid grid point, or as a pitch.
  expect_error("render panorama " + f.store + " " + out + " --dem dem --camera 45.02 100.15 1500",
               "--camera 45.02 100.15 1500: expected LON LAT HEIGHT");
  expect_error("render panorama " + f.store + " " + out + " --dem dem --camera 10.15 45.02 nan",
               "--camera 10.15 45.02 nan: expected LON LAT HEIGHT");
  expect_error(f.render(out, "--look-at 10.15 nan 700"), "--look-at 10.15 nan 700: expected");
}

// OUT naming the store is refused and the store kept, from the command and from
// the export step: the picture replaced the store, exit 0.
TEST(PanoramaCli, OutputThatIsTheStoreIsRefused) {
  const Fixture& f = fixture();
  const std::string dir = test::temp_dir(), store = dir + "/kept.mqt";
  std::filesystem::copy_file(f.store, store);
  const std::string camera = " --dem dem --camera 10.15 45.02 1500 --size 20 10";
  auto r = run_maquette("render panorama " + store + " " + store + camera);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find(store + " is the store " + store + ": it would be replaced"),
            std::string::npos)
      << r.err;
  std::ofstream(dir + "/pipeline.json")
      << R"({"store": "kept.mqt", "region": {"bbox": [10, 45, 10.3, 45.3]}, "level": 9,
            "steps": [{"op": "export", "params": {"format": "panorama", "out": "kept.mqt",
            "dem": "dem", "camera": [10.15, 45.02, 1500], "size": [20, 10]}}]})";
  r = run_maquette("-q run " + dir + "/pipeline.json");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("is the store"), std::string::npos) << r.err;
  const auto info = run_maquette("info " + store);
  EXPECT_EQ(info.exit_code, 0) << info.err;
  EXPECT_NE(info.out.find("dem: raster float32"), std::string::npos) << info.out;
}

// A layer a run left incomplete is not drawn (it was, exit 0: an audit's find), as exports refuse
// it.
TEST(PanoramaCli, AnIncompleteLayerIsNotDrawn) {
  const Fixture& f = fixture();
  const std::string dir = test::temp_dir(), store = dir + "/cut.mqt";
  std::filesystem::copy_file(f.store, store);
  {
    const auto s = Store::open(store, Store::Mode::ReadWrite);
    s->mark_incomplete("dem", s->begin_run({{"steps", 1}}));
  }
  const auto r = run_maquette("render panorama " + store + " " + dir +
                              "/p.png --dem dem --camera 10.15 45.02 1500 --size 20 10");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("--dem: layer 'dem' in " + store + " is incomplete (run "),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/p.png"));
}

// OUT's extension says the picture's format (OUT.jpg was PNG bytes); another extension, or a
// directory that does not exist (told through the guides' file's name), is refused before drawing.
TEST(PanoramaCli, ThePicturesFormatIsItsExtensions) {
  const Fixture& f = fixture();
  const std::string dir = test::temp_dir();
  const auto r = run_maquette(f.render(dir + "/view.JPG", "--size 40 20"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto magic = [](const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string bytes(4, '\0');
    in.read(bytes.data(), 4);
    return bytes;
  };
  EXPECT_EQ(magic(dir + "/view.JPG").substr(0, 3), "\xFF\xD8\xFF");  // JPEG's start of image
  EXPECT_EQ(magic(dir + "/view-silhouettes.png"), "\x89PNG");
  for (const auto& [out, message] :
       {std::pair<std::string, std::string>{dir + "/view.tif",
                                            "a panorama is written as PNG (.png) or JPEG (.jpg, "
                                            ".jpeg), not '.tif'"},
        {dir + "/nosuch/view.png", "the directory " + dir + "/nosuch does not exist"}}) {
    const auto bad = run_maquette(f.render(out, "--size 40 20"));
    EXPECT_NE(bad.exit_code, 0) << out;
    EXPECT_NE(bad.err.find(message), std::string::npos) << bad.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << out;
  }
}

// Terrain wholly beyond three haze distances (95 % haze colour) is a picture of haze: said, with
// the distance and the option to raise (a view from 40 km up drew nothing else, silently).
TEST(PanoramaCli, TerrainLostInTheHazeIsSaid) {
  const Fixture& f = fixture();
  const std::string dir = test::temp_dir();
  const std::string said = "all of it is drawn at least 95 % in the haze's colour";
  const auto hazed = run_maquette(f.render(dir + "/hazed.png", "--size 40 20 --haze-distance 50"));
  ASSERT_EQ(hazed.exit_code, 0) << hazed.err;
  EXPECT_NE(hazed.err.find(said), std::string::npos) << hazed.err;
  EXPECT_NE(hazed.err.find("times --haze-distance 50 m"), std::string::npos) << hazed.err;
  const auto clear = run_maquette(f.render(dir + "/clear.png", "--size 40 20"));
  ASSERT_EQ(clear.exit_code, 0) << clear.err;
  EXPECT_EQ(clear.err.find(said), std::string::npos) << clear.err;
}

}  // namespace
}  // namespace maquette
