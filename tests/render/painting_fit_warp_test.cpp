// The residual warp (formats/render/painting_fit_warp.h), a thin-plate spline: an affine motion
// is reproduced everywhere, the spline without smoothing moves each centre onto its target, a very
// smooth one tends to the least-squares affine motion (OpenCV's solve, SVD), and too few or
// collinear points are refused.
#include "render/painting_fit_warp.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/core.hpp>

#include "core/error.h"

namespace maquette {
namespace {

std::vector<PicturePoint> scattered() {
  std::vector<PicturePoint> p;
  for (int i = 0; i < 12; ++i) p.push_back({100 + 97.0 * i, 800 - 61.0 * ((i * 7) % 12)});
  return p;
}

PicturePoint affine(const PicturePoint& p) {
  return {3 + 1.01 * p[0] - 0.02 * p[1], -5 + 0.03 * p[0] + 0.98 * p[1]};
}

TEST(PictureWarp, ReproducesAnAffineMotion) {
  std::vector<PicturePoint> to;
  for (const auto& p : scattered()) to.push_back(affine(p));
  const PictureWarp warp(scattered(), to, 1600, 0);
  for (const PicturePoint p : {PicturePoint{0, 0}, {1600, 1000}, {333, 777}}) {
    EXPECT_NEAR(warp(p)[0], affine(p)[0], 1e-7);
    EXPECT_NEAR(warp(p)[1], affine(p)[1], 1e-7);
  }
  EXPECT_EQ(PictureWarp()(PicturePoint{5, 6}), (PicturePoint{5, 6}));
}

TEST(PictureWarp, InterpolatesOrSmooths) {
  const auto from = scattered();
  std::vector<PicturePoint> to;
  for (size_t i = 0; i < from.size(); ++i)
    to.push_back(
        {from[i][0] + 4 * std::sin(double(i)), from[i][1] + 3 * std::cos(2.0 * double(i))});
  const PictureWarp exact(from, to, 1600, 0);
  for (size_t i = 0; i < from.size(); ++i) {
    EXPECT_NEAR(exact(from[i])[0], to[i][0], 1e-7);
    EXPECT_NEAR(exact(from[i])[1], to[i][1], 1e-7);
  }
  // The least-squares affine motion of the displacements.
  cv::Mat a(int(from.size()), 3, CV_64F), b(int(from.size()), 2, CV_64F), x;
  for (int i = 0; i < int(from.size()); ++i) {
    a.at<double>(i, 0) = 1;
    a.at<double>(i, 1) = from[size_t(i)][0];
    a.at<double>(i, 2) = from[size_t(i)][1];
    b.at<double>(i, 0) = to[size_t(i)][0] - from[size_t(i)][0];
    b.at<double>(i, 1) = to[size_t(i)][1] - from[size_t(i)][1];
  }
  ASSERT_TRUE(cv::solve(a, b, x, cv::DECOMP_SVD));
  const PictureWarp smooth(from, to, 1600, 1e9);
  for (const PicturePoint p : {PicturePoint{0, 0}, {1600, 1000}, {333, 777}})
    for (int k = 0; k < 2; ++k)
      EXPECT_NEAR(smooth(p)[size_t(k)] - p[size_t(k)],
                  x.at<double>(0, k) + x.at<double>(1, k) * p[0] + x.at<double>(2, k) * p[1], 1e-4);
}

TEST(PictureWarp, RefusesTooFewOrCollinearPoints) {
  EXPECT_THROW(PictureWarp({{0, 0}, {1, 1}}, {{0, 0}, {1, 1}}, 10, 0), Error);
  EXPECT_THROW(PictureWarp({{0, 0}, {1, 1}, {2, 2}}, {{0, 0}, {1, 1}}, 10, 0), Error);
  EXPECT_THROW(
      PictureWarp({{0, 0}, {1, 1}, {2, 2}, {3, 3}}, {{0, 0}, {1, 1}, {2, 2}, {3, 4}}, 10, 0),
      Error);
}

}  // namespace
}  // namespace maquette
