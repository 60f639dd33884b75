// The painting fit (formats/render/painting_fit.h) on synthetic paintings (synthetic_painting.h:
// the tests' own pinhole and bend in PROJ's frame): clicks with 2 px of noise (root-mean-square
// length), the fitted camera's projections of other, held-out ground points against their true
// pixels. Plain: 15 clicks, the focal length unknown, median <= 1 px and the focal length within
// 0.5 %. Bent: 30 clicks, the bend fitted too, median <= 2.5 px and 90th percentile <= 6 px.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/error.h"
#include "synthetic_painting.h"

namespace maquette {
namespace {

using test::SyntheticPainting;

PaintingFitOptions options_for(const SyntheticPainting& p) {
  PaintingFitOptions o;
  o.width = p.camera.width;
  o.height = p.camera.height;
  o.ground_height = [](LonLat at) { return test::synthetic_terrain(at.lon, at.lat); };
  return o;
}

std::vector<GeodeticPoint> grounds(const std::vector<GroundClick>& clicks) {
  std::vector<GeodeticPoint> g;
  for (const GroundClick& c : clicks) g.push_back(c.ground);
  return g;
}

TEST(PaintingFit, ExactClicksGiveTheCameraBack) {
  const SyntheticPainting painting = test::plain_painting();
  std::mt19937 random(7);
  const auto clicks = painting.clicks(8, 0, random);
  const auto held_out = painting.clicks(100, 0, random);
  const PaintingFit fit = fit_painting(clicks, options_for(painting));
  EXPECT_LE(test::error_percentiles(painting, held_out,
                                    project_ground(fit.camera, fit.bend, grounds(held_out)))[1],
            0.01);
  EXPECT_NEAR(fit.camera.fov, painting.camera.fov, 1e-5);
  EXPECT_NEAR(fit.camera.heading, painting.camera.heading, 1e-5);
  EXPECT_NEAR(fit.camera.pitch, painting.camera.pitch, 1e-5);
  EXPECT_NEAR(fit.camera.eye.lon, painting.eye_lon, 1e-7);
  EXPECT_NEAR(fit.camera.eye.lat, painting.eye_lat, 1e-7);
  EXPECT_NEAR(fit.camera.eye.height, painting.eye_height, 0.01);
  EXPECT_LE(fit.rms_error, 0.01);
}

// The noise makes each painting's errors a draw: over 40 paintings (each 15 clicks, 200 held-out
// points), the median of their held-out medians is <= 1 px and the focal length is within 0.5 %
// in at least 38 of them (95 %).
TEST(PaintingFit, TooFewClicksOrABadFovAreNamed) {
  const SyntheticPainting painting = test::plain_painting();
  std::mt19937 random(7);
  const auto clicks = painting.clicks(4, 0, random);
  PaintingFitOptions options = options_for(painting);
  EXPECT_NO_THROW(fit_painting(clicks, options));
  options.bend = true;
  try {
    fit_painting(clicks, options);
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "painting fit: 4 control points for 8 unknowns: give at least 5");
  }
  options.bend = false;
  options.fov = 180;
  EXPECT_THROW(fit_painting(clicks, options), Error);
}

TEST(PaintingFit, PlainCameraFromFifteenClicks) {
  const SyntheticPainting painting = test::plain_painting();
  std::vector<double> medians;
  int focal_within = 0;
  for (unsigned seed = 1; seed <= 40; ++seed) {
    std::mt19937 random(seed);
    const auto clicks = painting.clicks(15, 2, random);
    const auto held_out = painting.clicks(200, 0, random);
    const PaintingFit fit = fit_painting(clicks, options_for(painting));
    EXPECT_FALSE(fit.bend.bends());
    medians.push_back(test::error_percentiles(
        painting, held_out, project_ground(fit.camera, fit.bend, grounds(held_out)))[0]);
    const double focal_error = PinholeCamera(fit.camera).focal() / painting.camera.focal() - 1;
    focal_within += std::abs(focal_error) <= 0.005;
  }
  std::sort(medians.begin(), medians.end());
  std::printf(
      "held-out medians over 40 paintings: median %.2f px, 90th percentile %.2f px, "
      "<= 1 px in %d; focal length within 0.5 %% in %d\n",
      medians[20], medians[36],
      int(std::upper_bound(medians.begin(), medians.end(), 1.0) - medians.begin()), focal_within);
  EXPECT_LE(medians[20], 1.0);
  EXPECT_GE(focal_within, 38);
}

// The held-out errors (median, 90th percentile) of fits of `painting` from `count` clicks, each of
// 40 paintings, over the paintings: the medians of both, and the worst of both.
struct Spread {
  double median, p90, worst_median, worst_p90;
};
Spread held_out_errors(const SyntheticPainting& painting, const PaintingFitOptions& options,
                       size_t count) {
  std::vector<double> medians, p90s;
  for (unsigned seed = 1; seed <= 40; ++seed) {
    std::mt19937 random(seed);
    const auto clicks = painting.clicks(count, 2, random);
    const auto held_out = painting.clicks(200, 0, random);
    const PaintingFit fit = fit_painting(clicks, options);
    const auto [median, p90] =
        test::error_percentiles(painting, held_out, fit.to_painting(grounds(held_out)));
    medians.push_back(median);
    p90s.push_back(p90);
  }
  std::sort(medians.begin(), medians.end());
  std::sort(p90s.begin(), p90s.end());
  return {medians[20], p90s[20], medians.back(), p90s.back()};
}

// Over 40 bent paintings (each 30 clicks, 200 held-out points), every painting's held-out median
// and 90th percentile are <= 2.5 and 6 px with the bend fitted; a plain camera and a spline
// (the baseline) leave far more.
TEST(PaintingFit, BentCameraFromThirtyClicks) {
  const SyntheticPainting painting = test::bent_painting();
  PaintingFitOptions options = options_for(painting);
  options.bend = true;
  const Spread bent = held_out_errors(painting, options, 30);
  options.bend = false;
  options.warp_smoothing = 0.001;
  const Spread baseline = held_out_errors(painting, options, 30);
  std::printf(
      "bent, held-out errors over 40 paintings: camera and bend: medians %.2f px (worst "
      "%.2f), 90th percentiles %.2f px (worst %.2f); plain camera and spline: %.2f (%.2f), "
      "%.2f px (%.2f)\n",
      bent.median, bent.worst_median, bent.p90, bent.worst_p90, baseline.median,
      baseline.worst_median, baseline.p90, baseline.worst_p90);
  EXPECT_LE(bent.worst_median, 2.5);
  EXPECT_LE(bent.worst_p90, 6.0);
  EXPECT_GT(baseline.median, 2 * bent.median);
}

// The painter's distortion (a bulge of 40 px in the middle of a bent painting) is beyond the
// camera and bend; the warp takes most of it away.
TEST(PaintingFit, WarpTakesAwayThePaintersDistortion) {
  SyntheticPainting painting = test::bent_painting();
  painting.bulge = 40;
  PaintingFitOptions options = options_for(painting);
  options.bend = true;
  const Spread unwarped = held_out_errors(painting, options, 30);
  options.warp_smoothing = 0.001;
  const Spread warped = held_out_errors(painting, options, 30);
  std::printf(
      "bent and bulged, held-out errors over 40 paintings: camera and bend: medians %.2f "
      "px, 90th percentiles %.2f px; with the warp: %.2f, %.2f px\n",
      unwarped.median, unwarped.p90, warped.median, warped.p90);
  EXPECT_GT(unwarped.median, 5.0);
  EXPECT_LE(warped.median, 2.5);
  EXPECT_LE(warped.p90, unwarped.p90 / 2);
}

}  // namespace
}  // namespace maquette
