// The ground warp of a painting fit (formats/render/painting_fit_ground.h) on a bent painting its
// painter bulged by 40 px (synthetic_painting.h), 30 clicks with 2 px of noise: each click's
// ground point moved as the warp says is drawn, by the tests' own pinhole and bend in PROJ's frame
// under the fitted camera and bend, where the picture warp sends its fitted pixel; the warp's
// source at that moved point is the ground point; far from the clicks the warp leaves points as
// they are, bit for bit.
#include "render/painting_fit_ground.h"

#include <gtest/gtest.h>

#include <cmath>
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
  const GroundWarp warp(fit);
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

}  // namespace
}  // namespace maquette
