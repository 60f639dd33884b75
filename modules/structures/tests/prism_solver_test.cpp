// structures.prism's solver against synthetic photos (prism_synthetic.h): 1,000 known prisms and
// cameras, clicks with 1-pixel noise, the recovered shape compared with the truth.
#include "../prism_solver.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <vector>

#include "core/error.h"
#include "prism_synthetic.h"

namespace maquette::structures {
namespace {

constexpr uint64_t kSeed = 20261129;
constexpr int kPhotos = 1000;

double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  return v[size_t(q * double(v.size() - 1))];
}

// Edge lengths: the profile's edges, then the extrusion.
std::vector<double> edge_lengths(const std::vector<Vec3>& profile, const Vec3& extrusion) {
  std::vector<double> out;
  for (size_t i = 0; i < profile.size(); ++i)
    out.push_back((profile[(i + 1) % profile.size()] - profile[i]).norm());
  out.push_back(extrusion.norm());
  return out;
}

double angle_deg(const std::vector<Vec3>& profile, int i) {
  const size_t n = profile.size();
  const Vec3 p = profile[size_t(i)];
  const Vec3 a = profile[(size_t(i) + n - 1) % n] - p, b = profile[(size_t(i) + 1) % n] - p;
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) * 180 /
         std::numbers::pi;
}

// How far a solution is from the truth in the solver's frame (corner depth 1).
double distance(const PrismSolution& s, const SyntheticPhoto& p) {
  double d =
      (s.extrusion - (p.to_solver_frame(Vec3(0, p.length, 0)) - p.to_solver_frame(Vec3::Zero())))
          .norm();
  for (size_t i = 0; i < s.profile.size(); ++i)
    d += (s.profile[i] - p.to_solver_frame(p.profile[i])).norm();
  return d;
}

struct Errors {
  std::vector<double> ratio, right_angle, focal;
  int wrong_root = 0, no_root = 0, two_roots = 0;
};

Errors solve_series(double noise_px, int more_extrusions, bool estimate_focal) {
  Errors e;
  for (int k = 0; k < kPhotos; ++k) {
    const SyntheticPhoto p = synthetic_photo(kSeed, k, noise_px, more_extrusions);
    PinholeCamera camera = p.camera;
    if (estimate_focal) camera.focal_px = std::hypot(p.width, p.height);
    const std::vector<PrismSolution> roots = prism_roots(p.clicks, camera);
    e.two_roots += roots.size() == 2;
    const std::optional<PrismSolution> kept = checked_root(roots);
    if (!kept) {
      ++e.no_root;
      continue;
    }
    // The right root is the one nearer the truth.
    for (const PrismSolution& r : roots)
      if (distance(r, p) < distance(*kept, p)) ++e.wrong_root;
    const PrismSolution s =
        solve_prism(p.clicks, camera, "photo " + std::to_string(k), estimate_focal);
    const std::vector<double> got = edge_lengths(s.profile, s.extrusion);
    const std::vector<double> truth = edge_lengths(p.profile, Vec3(0, p.length, 0));
    for (size_t i = 1; i < got.size(); ++i)
      e.ratio.push_back(std::abs((got[i] / got[0]) / (truth[i] / truth[0]) - 1));
    for (const int i : p.right_angles)
      e.right_angle.push_back(std::abs(angle_deg(s.profile, i) - 90));
    e.focal.push_back(std::abs(s.focal_px / p.camera.focal_px - 1));
  }
  return e;
}

void print(const char* what, const Errors& e) {
  std::cout << what << ": " << kPhotos << " photos, edge-ratio error median "
            << 100 * quantile(e.ratio, 0.5) << " % (95th percentile "
            << 100 * quantile(e.ratio, 0.95) << " %), right-angle error median "
            << quantile(e.right_angle, 0.5) << " deg (95th percentile "
            << quantile(e.right_angle, 0.95)
            << " deg), Eq. 9 gave two roots in front of the camera " << e.two_roots
            << " times, wrong root kept " << e.wrong_root << ", no root kept " << e.no_root << "\n";
}

TEST(PrismSolver, ExactClicksGiveTheExactPrism) {
  for (int k = 0; k < 50; ++k) {
    const SyntheticPhoto p = synthetic_photo(kSeed, k, 0);
    const PrismSolution s = solve_prism(p.exact, p.camera, "photo");
    EXPECT_LT(distance(s, p), 1e-9) << "photo " << k;
  }
}

TEST(PrismSolver, OracleOfOneThousandPhotosWithOnePixelNoise) {
  const Errors e = solve_series(1.0, 0, false);
  print("minimal clicks, focal length known", e);
  EXPECT_LE(quantile(e.ratio, 0.5), 0.02);
  EXPECT_LE(quantile(e.right_angle, 0.5), 1.0);
  EXPECT_EQ(e.wrong_root, 0);
  EXPECT_EQ(e.no_root, 0);
  EXPECT_GT(e.two_roots, 0);  // the check had roots to choose among
}

TEST(PrismSolver, MoreClickedEdgesReduceTheError) {
  const Errors minimal = solve_series(1.0, 0, false);
  const Errors more = solve_series(1.0, 2, false);
  print("two more extrusion ends, focal length known", more);
  EXPECT_LT(quantile(more.ratio, 0.5), quantile(minimal.ratio, 0.5));
  EXPECT_EQ(more.wrong_root, 0);
  EXPECT_EQ(more.no_root, 0);
}

TEST(PrismSolver, FocalLengthEstimatedFromMoreClickedEdges) {
  // Started from the image's diagonal (a 35 mm-equivalent focal length of 43 mm), 0.6-1.7 times
  // the truth.
  const Errors e = solve_series(1.0, 2, true);
  print("two more extrusion ends, focal length estimated", e);
  std::cout << "focal length error median " << 100 * quantile(e.focal, 0.5)
            << " % (95th percentile " << 100 * quantile(e.focal, 0.95) << " %)\n";
  EXPECT_LE(quantile(e.focal, 0.5), 0.1);
  EXPECT_LE(quantile(e.ratio, 0.5), 0.05);
  EXPECT_EQ(e.no_root, 0);
}

TEST(PrismSolver, DegenerateClicksAreRefusedByName) {
  PrismClicks c;
  c.profile = {{0, 0}, {10, 0}};
  EXPECT_THROW(solve_prism(c, {1000, {0, 0}}, "strokes.json"), Error);
  c.profile = {{0, 0}, {10, 0}, {20, 0}};
  c.extrusion = {0, 10};
  try {
    solve_prism(c, {1000, {0, 0}}, "strokes.json");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("strokes.json: the corner's edges"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace maquette::structures
