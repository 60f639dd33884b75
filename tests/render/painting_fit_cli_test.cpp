// `maquette render fit` on a synthetic DEM of terraces (flat steps, heights above the ellipsoid):
// control points at the terraces' centres, where the tests' own pinhole in PROJ's frame puts them,
// half with their height, half with the DEM's; the camera written is that pinhole's, and the
// panorama drawn under it (--panorama) has, at each control point's pixel, guides naming that
// point's lon/lat, its terrace's height and class; with the warp, the guides of a painting its
// painter stretched still name each click's ground point at its pixel; a bent painting's bend is
// found and its panorama puts the clicks' ground points on their pixels. Bad input named.
#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <numbers>

#include "proj_enu.h"
#include "render/painting_fit_job.h"
#include "run_cli.h"
#include "synthetic_raster.h"
#include "test_camera.h"

namespace maquette {
namespace {

using nlohmann::json;
using test::run_maquette;

// Terraces of 0.1 x 0.05 degrees; each flat.
int terrace(double lon, double lat) {
  return int(std::floor((lon - 10) / 0.1)) + 3 * int(std::floor((lat - 45) / 0.05));
}
double terrace_height(double lon, double lat) { return 100 + 37.0 * terrace(lon, lat); }

constexpr double kEyeLon = 10.15, kEyeLat = 44.96, kEyeHeight = 2500;
const test::TestCamera kCamera{3, -10, 55, 800, 500};

struct Fixture {
  std::string dir = test::temp_dir(), store = dir + "/s.mqt", points = dir + "/points.json";
  std::vector<std::array<double, 4>> clicks;  // x, y, lon, lat
  Fixture() {
    const std::string tif = dir + "/dem.tif", classes = dir + "/classes.tif";
    test::write_raster(tif, test::lonlat_raster(10, 45.3, 600, 0.0005, "Float32"),
                       [](int, double lon, double lat) { return terrace_height(lon, lat); });
    test::write_raster(classes, test::lonlat_raster(10, 45.3, 600, 0.0005, "Byte"),
                       [](int, double lon, double lat) { return 1 + terrace(lon, lat); });
    for (const std::string& ingest : {"--layer dem --as dem --vertical-datum ellipsoid " + tif,
                                      "--layer lc --as landcover " + classes}) {
      const auto r = run_maquette("ingest " + store + " " + ingest);
      EXPECT_EQ(r.exit_code, 0) << r.err;
    }
    const test::ProjEnu enu(kEyeLon, kEyeLat, kEyeHeight);
    json file{{"width", kCamera.width}, {"height", kCamera.height}, {"points", json::array()}};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 6; ++j) {
        const double lon = 10.05 + 0.1 * i, lat = 45.025 + 0.05 * j;
        const auto px = kCamera.project(enu({lon, lat}, terrace_height(lon, lat)));
        const double x = px[0] + 0.5, y = px[1] + 0.5;  // OpenCV's pixel centres are at integers
        if (x < 0 || y < 0 || x > kCamera.width || y > kCamera.height) continue;
        json p{{"x", x}, {"y", y}, {"lon", lon}, {"lat", lat}};
        if (clicks.size() % 2) p["height"] = terrace_height(lon, lat);
        file["points"].push_back(p);
        clicks.push_back({x, y, lon, lat});
      }
    std::ofstream(points) << file.dump();
  }
};

const Fixture& fixture() {
  static const Fixture f;
  return f;
}

json read_json(const std::string& path) {
  std::ifstream in(path);
  return json::parse(in);
}

TEST(PaintingFitCli, FindsTheCameraAndDrawsTheGuides) {
  const Fixture& f = fixture();
  ASSERT_GE(f.clicks.size(), 8u);
  const std::string out = f.dir + "/fit.json", pano = f.dir + "/pano.png";
  const auto r = run_maquette("render fit " + f.store + " " + f.points + " " + out +
                              " --dem dem --panorama " + pano + " --land-cover lc");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json fit = read_json(out);
  const json& camera = fit.at("camera");
  EXPECT_NEAR(camera.at("eye")[0].get<double>(), kEyeLon, 1e-6);
  EXPECT_NEAR(camera.at("eye")[1].get<double>(), kEyeLat, 1e-6);
  EXPECT_NEAR(camera.at("eye")[2].get<double>(), kEyeHeight, 0.1);
  EXPECT_NEAR(camera.at("heading").get<double>(), kCamera.heading, 1e-4);
  EXPECT_NEAR(camera.at("pitch").get<double>(), kCamera.pitch, 1e-4);
  EXPECT_NEAR(camera.at("fov").get<double>(), kCamera.fov, 1e-4);
  EXPECT_EQ(camera.at("size"), json({800, 500}));
  EXPECT_TRUE(fit.at("bend").is_null());
  EXPECT_TRUE(fit.at("warp").is_null());
  EXPECT_LE(fit.at("rms_error").get<double>(), 0.01);
  ASSERT_EQ(fit.at("points").size(), f.clicks.size());
  for (const json& p : fit.at("points")) EXPECT_LE(p.at("error").get<double>(), 0.01) << p;
  const std::string options = fit.at("render_options");
  EXPECT_EQ(options.rfind("--camera 10.1", 0), 0u) << options;
  EXPECT_NE(options.find(" --size 800 500"), std::string::npos) << options;
  EXPECT_EQ(options.find("--bend"), std::string::npos) << options;

  // The guides of the panorama under the fitted camera, at each control point's pixel.
  std::unique_ptr<GDALDataset> guides(
      GDALDataset::Open((f.dir + "/pano-guides.tif").c_str(), GDAL_OF_RASTER));
  ASSERT_TRUE(guides);
  ASSERT_EQ(guides->GetRasterXSize(), 800);
  const auto at = [&](int band, const std::array<double, 4>& c) {
    double v = 0;
    EXPECT_EQ(guides->GetRasterBand(band)->RasterIO(GF_Read, int(c[0]), int(c[1]), 1, 1, &v, 1, 1,
                                                    GDT_Float64, 0, 0),
              CE_None);
    return v;
  };
  // The pixel's ground point (lon, lat, altitude), projected by the true camera, lies within
  // that pixel.
  const test::ProjEnu enu(kEyeLon, kEyeLat, kEyeHeight);
  for (const auto& c : f.clicks) {
    EXPECT_EQ(at(1, c), terrace_height(c[2], c[3]));  // altitude
    EXPECT_EQ(at(5, c), 1 + terrace(c[2], c[3]));     // land cover
    const auto px = kCamera.project(enu({at(3, c), at(4, c)}, at(1, c)));
    EXPECT_LE(std::abs(px[0] + 0.5 - c[0]), 1.0);
    EXPECT_LE(std::abs(px[1] + 0.5 - c[1]), 1.0);
  }
}

TEST(PaintingFitCli, FitsTheWarpWhenAsked) {
  const Fixture& f = fixture();
  const std::string out = f.dir + "/warped.json";
  const auto r = run_maquette("render fit " + f.store + " " + f.points + " " + out +
                              " --dem dem --fov 55 --warp-smoothing 0.001");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json fit = read_json(out);
  EXPECT_EQ(fit.at("camera").at("fov").get<double>(), 55);
  EXPECT_EQ(fit.at("warp").at("centres").size(), f.clicks.size());
  EXPECT_EQ(fit.at("warp").at("scale").get<double>(), 800);
  // Exact clicks: nothing left to warp.
  for (const json& w : fit.at("warp").at("weights")) {
    EXPECT_NEAR(w[0].get<double>(), 0, 1e-3);
    EXPECT_NEAR(w[1].get<double>(), 0, 1e-3);
  }
}

// The painter's stretch: a smooth distortion of the picture, up to 24 px.
std::array<double, 2> stretched(double x, double y) {
  return {x + 24 * std::sin(std::numbers::pi * y / kCamera.height),
          y + 18 * std::sin(std::numbers::pi * x / kCamera.width)};
}

// The largest distance, over the clicks, from a click to where the true camera, stretched, puts
// the ground point that the guides of `guides` name at the click's pixel (x, y of each click
// read; lon, lat not).
double worst_guide(const std::string& guides_path,
                   const std::vector<std::array<double, 4>>& clicks) {
  std::unique_ptr<GDALDataset> guides(GDALDataset::Open(guides_path.c_str(), GDAL_OF_RASTER));
  EXPECT_TRUE(guides);
  if (!guides) return 1e9;
  const test::ProjEnu enu(kEyeLon, kEyeLat, kEyeHeight);
  double worst = 0;
  for (const auto& c : clicks) {
    double v[5] = {};
    for (int band = 1; band <= 4; ++band)
      EXPECT_EQ(guides->GetRasterBand(band)->RasterIO(GF_Read, int(c[0]), int(c[1]), 1, 1, &v[band],
                                                      1, 1, GDT_Float64, 0, 0),
                CE_None);
    const auto px = kCamera.project(enu({v[3], v[4]}, v[1]));
    const auto p = stretched(px[0] + 0.5, px[1] + 0.5);
    worst = std::max(worst, std::hypot(p[0] - c[0], p[1] - c[1]));
  }
  return worst;
}

// A painting stretched by its painter: the warp moves the panorama and its guides onto it, so the
// guides at each click's pixel name the click's ground point; without the warp they miss.
TEST(PaintingFitCli, WarpedGuidesFollowThePainting) {
  const Fixture& f = fixture();
  json file{{"width", kCamera.width}, {"height", kCamera.height}, {"points", json::array()}};
  std::vector<std::array<double, 4>> clicks;
  for (const auto& c : f.clicks) {
    const auto p = stretched(c[0], c[1]);
    file["points"].push_back({{"x", p[0]},
                              {"y", p[1]},
                              {"lon", c[2]},
                              {"lat", c[3]},
                              {"height", terrace_height(c[2], c[3])}});
    clicks.push_back({p[0], p[1], c[2], c[3]});
  }
  const std::string points = f.dir + "/stretched.json";
  std::ofstream(points) << file.dump();
  const std::string fit = "render fit " + f.store + " " + points + " " + f.dir +
                          "/stretched-fit.json --dem dem --panorama ";
  ASSERT_EQ(run_maquette(fit + f.dir + "/warped.png --warp-smoothing 0.001").exit_code, 0);
  ASSERT_EQ(run_maquette(fit + f.dir + "/unwarped.png").exit_code, 0);
  const double warped = worst_guide(f.dir + "/warped-guides.tif", clicks),
               unwarped = worst_guide(f.dir + "/unwarped-guides.tif", clicks);
  std::printf("stretched painting: guides at the clicks %.2f px off with the warp, %.2f without\n",
              warped, unwarped);
  EXPECT_LE(warped, 2.0);
  EXPECT_GT(unwarped, 5.0);
  // The painting's left edge shows what the fitted camera draws up to 24 px beyond its picture
  // (the clicks lie inside it, so the spline extrapolates there): drawn wider, not
  // the guides of the picture's edge repeated (those of the panorama without the warp).
  std::vector<std::array<double, 4>> edge;
  for (int row = 100; row <= 400; row += 50) edge.push_back({0.5, row + 0.5, 0, 0});
  const double at_edge = worst_guide(f.dir + "/warped-guides.tif", edge),
               repeated = worst_guide(f.dir + "/unwarped-guides.tif", edge);
  std::printf("the guides on the painting's left edge %.2f px off, its own edge's %.2f px\n",
              at_edge, repeated);
  EXPECT_LE(at_edge, repeated / 2);
}

// A warp reaching far beyond the picture (what a spline extrapolating past bunched clicks does):
// the picture stretched four times across about its centre, so the left edge is sent 1200 px
// beyond it. The wide view is drawn with a margin of half the picture's larger side (400 px), not
// as far as the warp reaches (a view of 3200 x 500 pixels and more), and the edge takes the wide
// view's edge: the guides there name ground points the true camera draws 400 px left of the
// picture, on the same row; a pixel near the centre, the ground point it is sent to.
TEST(PaintingFitCli, AFarReachingWarpIsCapped) {
  const Fixture& f = fixture();
  const std::vector<PicturePoint> from = {{0, 0}, {800, 0}, {0, 500}, {800, 500}, {400, 250}};
  std::vector<PicturePoint> to;
  for (const auto& p : from) to.push_back({400 + 4 * (p[0] - 400), p[1]});
  PanoramaJob render;
  render.dem = "dem";
  render.camera = {{kEyeLon, kEyeLat, kEyeHeight},
                   kCamera.heading,
                   kCamera.pitch,
                   kCamera.fov,
                   kCamera.width,
                   kCamera.height};
  const auto store = Store::open(f.store, Store::Mode::ReadOnly);
  const Panorama p =
      render_warped_panorama(*store, default_grid(), render, PictureWarp(from, to, 800, 0));
  ASSERT_EQ(p.width, kCamera.width);
  ASSERT_EQ(p.height, kCamera.height);
  const test::ProjEnu enu(kEyeLon, kEyeLat, kEyeHeight);
  auto drawn_at = [&](int col, int row) {
    const size_t i = size_t(row) * size_t(p.width) + size_t(col);
    const auto px = kCamera.project(enu(p.lonlat(i), p.altitude[i]));
    return std::array<double, 2>{px[0] + 0.5, px[1] + 0.5};
  };
  int on_ground = 0;
  for (int row = 0; row < kCamera.height; row += 10) {
    if (std::isnan(p.altitude[size_t(row) * size_t(p.width)])) continue;
    ++on_ground;
    const auto at = drawn_at(0, row);
    EXPECT_NEAR(at[0], 0.5 - 400, 1.0) << row;
    EXPECT_NEAR(at[1], row + 0.5, 1.0) << row;
  }
  std::printf("the left edge: %d of %d rows on the ground\n", on_ground, kCamera.height / 10);
  EXPECT_GE(on_ground, 5);
  // Pixel (400, 250) is sent 4 times its 0.5 px from the centre: into pixel 402.
  const auto centre = drawn_at(400, 250);
  EXPECT_NEAR(centre[0], 402.5, 1.0);
  EXPECT_NEAR(centre[1], 250.5, 1.0);
}

// A bent painting seen from above the terraces (the bend's base on the DEM under the eye, 137 m):
// the fitted camera and bend draw each click's ground point on its pixel when `render fit
// --panorama` renders them, as `render panorama` does.
TEST(PaintingFitCli, BentPaintingGuides) {
  const Fixture& f = fixture();
  const double eye_lat = 45.005, radius = 30000, start = 4000;
  const test::ProjEnu enu(kEyeLon, eye_lat, kEyeHeight);
  json file{{"width", kCamera.width}, {"height", kCamera.height}, {"points", json::array()}};
  std::vector<std::array<double, 4>> clicks;
  // Two points across and two along each terrace, each 0.0125 degrees or more from its edges.
  for (int i = 0; i < 6; ++i)
    for (int j = 1; j < 12; ++j) {
      const double lon = 10.025 + 0.05 * i, lat = 45.0125 + 0.025 * j;
      const auto p = test::bent(enu({lon, lat}, terrace_height(lon, lat)), radius, start,
                                terrace_height(kEyeLon, eye_lat) - kEyeHeight);
      const auto px = kCamera.project(p);
      const double x = px[0] + 0.5, y = px[1] + 0.5;
      if (x < 0 || y < 0 || x > kCamera.width || y > kCamera.height) continue;
      file["points"].push_back({{"x", x}, {"y", y}, {"lon", lon}, {"lat", lat}});
      clicks.push_back({x, y, lon, lat});
    }
  ASSERT_GE(clicks.size(), 8u);
  const std::string points = f.dir + "/bent.json", out = f.dir + "/bent-fit.json";
  std::ofstream(points) << file.dump();
  const auto r = run_maquette("render fit " + f.store + " " + points + " " + out +
                              " --dem dem --bend --fov 55 --panorama " + f.dir + "/bent.png");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json fit = read_json(out);
  EXPECT_LE(fit.at("rms_error").get<double>(), 0.01);
  EXPECT_NEAR(fit.at("bend").at("radius").get<double>(), radius, 0.01 * radius);
  EXPECT_NEAR(fit.at("bend").at("start").get<double>(), start, 0.01 * start);
  std::unique_ptr<GDALDataset> guides(
      GDALDataset::Open((f.dir + "/bent-guides.tif").c_str(), GDAL_OF_RASTER));
  ASSERT_TRUE(guides);
  for (const auto& c : clicks) {
    double v[2] = {};
    for (int band : {3, 4})
      EXPECT_EQ(guides->GetRasterBand(band)->RasterIO(GF_Read, int(c[0]), int(c[1]), 1, 1,
                                                      &v[band - 3], 1, 1, GDT_Float64, 0, 0),
                CE_None);
    const auto p =
        kCamera.project(test::bent(enu({v[0], v[1]}, terrace_height(v[0], v[1])), radius, start,
                                   terrace_height(kEyeLon, eye_lat) - kEyeHeight));
    EXPECT_LE(std::hypot(p[0] + 0.5 - c[0], p[1] + 0.5 - c[1]), 1.0) << c[2] << " " << c[3];
  }
}

// --panorama's look is `render panorama`'s: --shadows adds the cast_shadow guide under --sun,
// --haze-distance hazes the picture, --smooth-land-cover changes the land_cover guide along the
// terraces' edges (a polar face's cells there: staircases) and not the picture.
TEST(PaintingFitCli, PanoramaTakesTheLookOptions) {
  const Fixture& f = fixture();
  const std::string fit = "render fit " + f.store + " " + f.points + " " + f.dir +
                          "/look.json --dem dem --panorama " + f.dir;
  ASSERT_EQ(run_maquette(fit + "/plain.png --land-cover lc").exit_code, 0);
  ASSERT_EQ(run_maquette(fit + "/smooth.png --land-cover lc --smooth-land-cover").exit_code, 0);
  ASSERT_EQ(run_maquette(fit + "/look.png --shadows --sun 200 20 --haze-distance 3000").exit_code,
            0);
  std::unique_ptr<GDALDataset> guides(
      GDALDataset::Open((f.dir + "/look-guides.tif").c_str(), GDAL_OF_RASTER));
  ASSERT_TRUE(guides);
  bool cast_shadow = false;
  for (int band = 1; band <= guides->GetRasterCount(); ++band)
    cast_shadow |= std::string(guides->GetRasterBand(band)->GetDescription()) == "cast_shadow";
  EXPECT_TRUE(cast_shadow);
  const auto bytes = [](const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  EXPECT_NE(bytes(f.dir + "/plain.png"), bytes(f.dir + "/look.png"));
  EXPECT_EQ(bytes(f.dir + "/plain.png"), bytes(f.dir + "/smooth.png"));
  auto land_cover = [](const std::string& path) {
    std::unique_ptr<GDALDataset> g(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER));
    EXPECT_TRUE(g);
    std::vector<double> v(size_t(kCamera.width) * size_t(kCamera.height));
    if (!g) return v;
    EXPECT_EQ(g->GetRasterBand(5)->RasterIO(GF_Read, 0, 0, kCamera.width, kCamera.height, v.data(),
                                            kCamera.width, kCamera.height, GDT_Float64, 0, 0),
              CE_None);
    return v;
  };
  const auto cells = land_cover(f.dir + "/plain-guides.tif"),
             smooth = land_cover(f.dir + "/smooth-guides.tif");
  size_t changed = 0;
  for (size_t i = 0; i < cells.size(); ++i)
    changed += cells[i] != smooth[i] && !std::isnan(cells[i]);
  EXPECT_GT(changed, 100u);
  EXPECT_LT(changed, cells.size() / 20);
  const auto r = run_maquette(fit + "/low.png --shadows --sun 200 0");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("--sun altitude"), std::string::npos) << r.err;
}

void expect_error(const std::string& args, const std::string& message) {
  const auto r = run_maquette(args);
  EXPECT_NE(r.exit_code, 0) << args;
  EXPECT_NE(r.err.find(message), std::string::npos) << args << "\n" << r.err;
}

TEST(PaintingFitCli, BadInputIsNamed) {
  const Fixture& f = fixture();
  const std::string out = f.dir + "/bad.json", fit = "render fit " + f.store + " ";
  expect_error(fit + f.dir + "/none.json " + out + " --dem dem",
               f.dir + "/none.json: cannot be read");
  expect_error(fit + f.points + " " + out + " --dem nope", "--dem layer 'nope'");
  expect_error(
      fit + f.points + " " + out + " --dem dem --panorama " + f.dir + "/x.png --land-cover dem",
      "--land-cover layer 'dem' is not categorical");
  const std::string far = f.dir + "/far.json";
  std::ofstream(far) << R"({"width": 800, "height": 500, "points": [
    {"x": 1, "y": 1, "lon": 10.1, "lat": 45.1}, {"x": 2, "y": 1, "lon": 10.2, "lat": 45.1},
    {"x": 3, "y": 1, "lon": 10.1, "lat": 45.2}, {"name": "far", "x": 4, "y": 1, "lon": 12, "lat": 45.2}]})";
  expect_error(fit + far + " " + out + " --dem dem",
               far +
                   ": points[3] (far) has no height and the --dem layer 'dem' has no data at lon "
                   "12, lat 45.2");
  expect_error(fit + f.points + " " + out + " --dem dem --fov 200", "--fov");
  const auto negative = run_maquette(fit + f.points + " " + out + " --dem dem --warp-smoothing -1");
  EXPECT_NE(negative.exit_code, 0);
  EXPECT_NE(negative.err.find("--warp-smoothing: expected a number >= 0, got -1"),
            std::string::npos)
      << negative.err;
  EXPECT_LT(negative.err.size(), 300u) << negative.err;  // it printed DBL_MAX's 309 digits
  expect_error(fit + f.points + " " + out + " --dem lc",
               "--dem layer 'lc' is categorical (classes, not heights)");
  // Every click on one pixel: OpenCV's SQPnP asserted, an internal error (exit 3).
  const std::string one_pixel = f.dir + "/one_pixel.json";
  std::ofstream(one_pixel) << R"({"width": 800, "height": 500, "points": [
    {"x": 9, "y": 9, "lon": 10.1, "lat": 45.1}, {"x": 9, "y": 9, "lon": 10.2, "lat": 45.1},
    {"x": 9, "y": 9, "lon": 10.1, "lat": 45.2}, {"x": 9, "y": 9, "lon": 10.2, "lat": 45.2}]})";
  const auto r = run_maquette(fit + one_pixel + " " + out + " --dem dem");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("solvePnP found no camera: are the control points spread"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(std::ifstream(out));  // nothing written
  EXPECT_FALSE(std::ifstream(f.dir + "/x.png"));
}

// What `render fit` of the fixture's own clicks prints (it succeeds).
std::string fixture_fit_log(const Fixture& f) {
  const auto r =
      run_maquette("render fit " + f.store + " " + f.points + " " + f.dir + "/good.json --dem dem");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return r.err;
}

// Clicks the fit cannot put where they were clicked (the painting mirrored: each pixel paired with
// another place) are warned of by name; the fixture's own clicks are not.
TEST(PaintingFitCli, FarClicksAreWarnedOf) {
  const Fixture& f = fixture();
  const std::string good = fixture_fit_log(f);
  EXPECT_EQ(good.find("clicks land farther"), std::string::npos) << good;
  json mirrored = read_json(f.points);
  for (json& p : mirrored.at("points")) p["x"] = kCamera.width - p.at("x").get<double>();
  const std::string path = f.dir + "/mirrored.json";
  std::ofstream(path) << mirrored.dump();
  const auto r = run_maquette("render fit " + f.store + " " + path + " " + f.dir +
                              "/mirrored-fit.json --dem dem");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: " + path + ": "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(" clicks land farther than 18.9 px (2 % of the painting's diagonal) from "
                       "where they were clicked (points[0] by "),
            std::string::npos)
      << r.err;
}

// Clicks along one meridian (the fixture's at lon 10.15: 28 km of terraces) leave the camera's
// turn about it to their heights: warned of; the fixture's three columns are not.
TEST(PaintingFitCli, ClicksOnOneLineOfTheMapAreWarnedOf) {
  const Fixture& f = fixture();
  const std::string good = fixture_fit_log(f);
  EXPECT_EQ(good.find("nearly on one line"), std::string::npos) << good;
  json line = read_json(f.points), points = json::array();
  for (const json& p : line.at("points"))
    if (p.at("lon").get<double>() == 10.15) points.push_back(p);
  line["points"] = points;
  ASSERT_GE(points.size(), 4u);
  const std::string path = f.dir + "/line.json";
  std::ofstream(path) << line.dump();
  const auto r =
      run_maquette("render fit " + f.store + " " + path + " " + f.dir + "/line-fit.json --dem dem");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: " + path + ": the " + std::to_string(points.size()) +
                       " control points lie nearly on one line of the map (0 m across it, "),
            std::string::npos)
      << r.err;
}

// OUT or --panorama naming an input (the store, the clicks) is refused, and the input kept: the
// fit's JSON replaced the store, or the user's clicks, exit 0.
TEST(PaintingFitCli, OutputsSpareTheInputs) {
  const Fixture& f = fixture();
  const std::string store = f.dir + "/kept.mqt", points = f.dir + "/kept.json";
  std::filesystem::copy_file(f.store, store);
  std::filesystem::copy_file(f.points, points);
  const std::string fit = "render fit " + store + " " + points + " ";
  expect_error(fit + store + " --dem dem", store + " is the store " + store + ": it would be");
  expect_error(fit + points + " --dem dem",
               points + " is the control points " + points + ": it would be replaced");
  expect_error(fit + f.dir + "/ok.json --dem dem --panorama " + store, "is the store");
  // --panorama's format, from its extension, checked before the fit writes OUT.
  expect_error(fit + f.dir + "/ok.json --dem dem --panorama " + f.dir + "/view.tif",
               "a panorama is written as PNG (.png) or JPEG (.jpg, .jpeg), not '.tif'");
  // OUT and --panorama one file: the picture replaced the fit, exit 0 (an audit's find).
  expect_error(fit + f.dir + "/same.png --dem dem --panorama " + f.dir + "/./same.png",
               f.dir + "/./same.png is both OUT and --panorama: give them other paths");
  EXPECT_FALSE(std::ifstream(f.dir + "/same.png"));
  EXPECT_EQ(run_maquette("info " + store).exit_code, 0);
  EXPECT_EQ(read_json(points), read_json(f.points));
  EXPECT_FALSE(std::ifstream(f.dir + "/ok.json"));
}

// A panorama file that cannot be written leaves neither the fit nor the panorama's other files
// (the fit and the picture were left when the silhouettes failed).
TEST(PaintingFitCli, AFileThatCannotBeWrittenLeavesNone) {
  const Fixture& f = fixture();
  const std::string dir = f.dir + "/unwritable";
  std::filesystem::create_directories(dir + "/view-silhouettes.png");  // a directory in the way
  expect_error("render fit " + f.store + " " + f.points + " " + dir + "/fit.json --dem dem " +
                   "--panorama " + dir + "/view.png",
               "cannot write " + dir + "/view-silhouettes.png: Is a directory");
  for (const char* name : {"/fit.json", "/view.png", "/view-guides.tif"})
    EXPECT_FALSE(std::filesystem::exists(dir + name)) << name;
  std::vector<std::string> left;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    left.push_back(entry.path().filename().string());
  EXPECT_EQ(left, std::vector<std::string>{"view-silhouettes.png"});
}

}  // namespace
}  // namespace maquette
