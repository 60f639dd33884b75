// The ground warp of a painting fit (formats/render/painting_fit_ground.h) on a bent painting its
// painter bulged by 40 px (synthetic_painting.h), 30 clicks with 2 px of noise: each click's
// ground point moved as the warp says is drawn, by the tests' own pinhole and bend in PROJ's frame
// under the fitted camera and bend, where the picture warp sends its fitted pixel; the warp's
// source at that moved point is the ground point; far from the clicks the warp leaves points as
// they are, bit for bit.
#include "render/painting_fit_ground.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "synthetic_painting.h"

namespace maquette {
namespace {

TEST(PaintingFitGround, MovedGroundPointsAreDrawnWhereTheWarpSendsThem) {
  test::SyntheticPainting painting = test::bent_painting();
  painting.bulge = 40;
  std::mt19937 random(7);
  const auto clicks = painting.clicks(30, 2, random);
  PaintingFitOptions options;
  options.width = painting.camera.width;
  options.height = painting.camera.height;
  options.bend = true;
  options.warp_smoothing = 0.001;
  options.ground_height = [](LonLat at) { return test::synthetic_terrain(at.lon, at.lat); };
  const PaintingFit fit = fit_painting(clicks, options);
  const GroundWarp warp(fit, 30);
  ASSERT_EQ(warp.moves().size(), clicks.size());

  const CameraSpec& c = fit.camera;
  const test::ProjEnu enu(c.eye.lon, c.eye.lat, c.eye.height);
  const test::TestCamera camera{c.heading, c.pitch, c.fov, c.width, c.height};
  const EnuFrame eye(c.eye);
  double largest_move = 0;
  for (size_t i = 0; i < clicks.size(); ++i) {
    const GeodeticPoint& g = clicks[i].ground;
    const auto at = eye.to_enu(g.lon, g.lat, 0);
    const auto& move = warp.moves()[i];
    const GeodeticPoint moved = eye.to_geodetic(at[0] + move[0], at[1] + move[1], at[2]);
    const auto px = camera.project(test::bent(enu({moved.lon, moved.lat}, g.height),
                                              fit.bend.radius, fit.bend.start, fit.bend.base));
    const auto target = fit.warp(fit.fitted[i]);
    EXPECT_NEAR(px[0] + 0.5, target[0], 0.01) << i;
    EXPECT_NEAR(px[1] + 0.5, target[1], 0.01) << i;
    const LonLat source = warp.source({moved.lon, moved.lat});
    const auto s = enu(source, g.height), t = enu({g.lon, g.lat}, g.height);
    EXPECT_LE(std::hypot(s[0] - t[0], s[1] - t[1]), 0.01) << i;  // metres
    EXPECT_FALSE(warp.still_near({moved.lon, moved.lat}, 0)) << i;
    largest_move = std::max(largest_move, std::hypot(move[0], move[1]));
  }
  std::printf("the bulge moves the clicks' ground points by up to %.0f m\n", largest_move);
  EXPECT_GT(largest_move, 100);
  // 1.5 degrees south of the clicks: out of reach.
  const LonLat far{10.2, 43.4};
  EXPECT_TRUE(warp.still_near(far, 1000));
  const LonLat source = warp.source(far);
  EXPECT_EQ(source.lon, far.lon);
  EXPECT_EQ(source.lat, far.lat);
}

// Two clicks 5 m apart on the ground (a bridge's two ends), far closer than the DEM's 30 m
// samples, 10 km from three others: the plain painting's camera, its picture moved 20 px right
// by the warp. The DEM's samples around the pair, 1.5 samples away, take the pair's whole move
// (within 2 % of its length), so the feature the two mark is drawn where the painting has it;
// with a reach of the 5 m between them the move faded out 10 m from them, and those samples
// stayed where they were.
TEST(PaintingFitGround, ClicksCloserThanASampleMoveTheSamplesAroundThem) {
  const test::SyntheticPainting painting = test::plain_painting();
  PaintingFit fit;
  fit.camera = {{painting.eye_lon, painting.eye_lat, painting.eye_height},
                painting.camera.heading,
                painting.camera.pitch,
                painting.camera.fov,
                painting.camera.width,
                painting.camera.height};
  const EnuFrame eye(fit.camera.eye);
  // East and north of the eye, metres: the pair 15 km ahead, the others 25 km ahead.
  for (const auto& [east, north] : std::vector<std::array<double, 2>>{
           {0, 15000}, {5, 15000}, {-2000, 25000}, {2000, 25000}, {0, 27000}}) {
    GeodeticPoint g = eye.to_geodetic(east, north, 0);
    g.height = test::synthetic_terrain(g.lon, g.lat);
    fit.ground.push_back(g);
  }
  fit.fitted = project_ground(fit.camera, fit.bend, fit.ground);
  std::vector<PicturePoint> moved;
  for (const auto& p : fit.fitted) moved.push_back({p[0] + 20, p[1]});
  fit.warp = PictureWarp(fit.fitted, moved, painting.camera.width, 0);
  const GroundWarp warp(fit, 30);
  EXPECT_EQ(warp.reach()[0], 60);
  EXPECT_EQ(warp.reach()[1], 60);

  const auto& move = warp.moves()[0];
  const double length = std::hypot(move[0], move[1]);
  std::printf("the pair's ground points move by %.0f m\n", length);
  ASSERT_GT(length, 100);
  const auto at = eye.to_enu(fit.ground[0].lon, fit.ground[0].lat, 0);
  for (int k = 0; k < 8; ++k) {
    const double angle = k * std::numbers::pi / 4;
    const double east = at[0] + move[0] + 45 * std::cos(angle),
                 north = at[1] + move[1] + 45 * std::sin(angle);
    const GeodeticPoint p = eye.to_geodetic(east, north, at[2]);
    const LonLat source = warp.source({p.lon, p.lat});
    const auto s = eye.to_enu(source.lon, source.lat, 0);
    EXPECT_LE(std::hypot(east - s[0] - move[0], north - s[1] - move[1]), 0.02 * length) << k;
  }
}

}  // namespace
}  // namespace maquette
