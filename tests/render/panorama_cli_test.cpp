// `maquette render panorama` on a synthetic DEM (a 600 m plateau on a plain, heights above the
// ellipsoid): every terrain pixel's guides (lon, lat, altitude) name a point that the test's own
// pinhole puts back on that pixel's centre (<= 0.05 px) at the guide's distance (PROJ's
// east-north-up frame, not the program's GeographicLib), the plateau's edge drawn as a
// silhouette, the land-cover guide the class at the guide's lon/lat; --look-at and --above-ground
// aim and place the camera where PROJ says, --exaggeration scales the heights; a bent panorama
// (--bend-radius) puts each guide point where the test's own bend of PROJ's point projects, its
// horizon higher than the unbent one's, an infinite radius the unbent picture bit for bit; the
// same bytes for 1 and 2 threads, bent or not; bad input named.
#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <sstream>

#include "proj_enu.h"
#include "run_cli.h"
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
  ASSERT_EQ(guides->GetRasterCount(), 5);
  EXPECT_STREQ(guides->GetRasterBand(2)->GetDescription(), "distance");
  EXPECT_STREQ(guides->GetRasterBand(5)->GetDescription(), "land_cover");
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
  expect_error(f.render(out, "--fov 175"), "camera fov 175");
  expect_error(f.render(out, "--fov 0"), "out of range");
  expect_error(f.render(out, "--bend-radius -300"), "--bend-radius -300");
  expect_error(f.render(out, "--bend-radius 9000 --bend-start -5"), "--bend-start -5");
}

}  // namespace
}  // namespace maquette
