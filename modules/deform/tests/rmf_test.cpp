// Rotation-minimizing frames against the analytic RMF of a helix: (a cos t, a sin t, c t) has
// curvature a / (a^2 + c^2) and torsion tau = c / (a^2 + c^2); its RMF normal is
// cos(theta) N + sin(theta) B with theta = -tau s (s the arc length), N, B the Frenet frame.
#include "../rmf.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace maquette::deform {
namespace {

double angle(const Vec3d& u, const Vec3d& v) {
  const Vec3d c{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  return std::atan2(std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]),
                    u[0] * v[0] + u[1] * v[1] + u[2] * v[2]);
}

TEST(RotationMinimizingFrames, HelixOneTurnTwistsLessThanMicroradian) {
  const double a = 30, c = 8, w = std::sqrt(a * a + c * c), tau = c / (w * w);
  const int n = 4000;
  std::vector<Vec3d> points, tangents, expected;
  for (int i = 0; i <= n; ++i) {
    const double t = 2 * std::numbers::pi * i / n;
    points.push_back({a * std::cos(t), a * std::sin(t), c * t});
    tangents.push_back({-a * std::sin(t) / w, a * std::cos(t) / w, c / w});
    const Vec3d normal{-std::cos(t), -std::sin(t), 0};
    const Vec3d binormal{c * std::sin(t) / w, -c * std::cos(t) / w, a / w};
    const double theta = -tau * w * t;
    expected.push_back({std::cos(theta) * normal[0] + std::sin(theta) * binormal[0],
                        std::cos(theta) * normal[1] + std::sin(theta) * binormal[1],
                        std::cos(theta) * normal[2] + std::sin(theta) * binormal[2]});
  }
  const std::vector<Frame> frames = rotation_minimizing_frames(points, tangents, expected[0]);
  ASSERT_EQ(frames.size(), points.size());
  double worst = 0;
  for (size_t i = 0; i < frames.size(); ++i)
    worst = std::max(worst, angle(frames[i].reference, expected[i]));
  EXPECT_LE(worst, 1e-6);
  // The frame really turned: theta over one turn is -2 pi c / w, about -1.6 rad.
  EXPECT_GT(angle(frames.back().reference, {-1, 0, 0}), 1.0);
}

TEST(RotationMinimizingFrames, PlanarCurveKeepsItsInPlaneNormal) {
  // A coarse circle in the horizontal plane: the frame stays the horizontal normal, exactly.
  std::vector<Vec3d> points, tangents;
  for (int i = 0; i <= 12; ++i) {
    const double t = 2 * std::numbers::pi * i / 12;
    points.push_back({std::cos(t), std::sin(t), 0});
    tangents.push_back({-std::sin(t), std::cos(t), 0});
  }
  const std::vector<Frame> frames = rotation_minimizing_frames(points, tangents, {1, 0, 0});
  for (size_t i = 0; i < frames.size(); ++i) {
    EXPECT_NEAR(frames[i].reference[2], 0, 1e-15);
    EXPECT_NEAR(angle(frames[i].reference, {points[i][0], points[i][1], 0}), 0, 1e-12) << i;
  }
}

}  // namespace
}  // namespace maquette::deform
