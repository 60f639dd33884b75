#include "render/painting_fit_warp.h"

#include <Eigen/Dense>
#include <cmath>
#include <string>

#include "core/error.h"

namespace maquette {
namespace {

// U(r) of the spline from the squared distance: r^2 log r = r2 log(r2) / 2, 0 at 0.
double kernel(double r2) { return r2 > 0 ? 0.5 * r2 * std::log(r2) : 0; }

}  // namespace

PictureWarp::PictureWarp(const std::vector<PicturePoint>& from, const std::vector<PicturePoint>& to,
                         double scale, double smoothing)
    : centres_(from), scale_(scale) {
  const auto n = Eigen::Index(from.size());
  if (from.size() != to.size() || n < 3)
    throw Error("warp: " + std::to_string(from.size()) + " points to move onto " +
                std::to_string(to.size()) + ": the spline needs as many, at least 3");
  if (!(scale > 0) || !(smoothing >= 0))
    throw Error("warp: scale " + std::to_string(scale) + " or smoothing " +
                std::to_string(smoothing) + " out of range");
  // The system [K + lambda I, P; P^T, 0] [w; a] = [v; 0], its kernel block divided by 1 + lambda
  // and its unknowns w times and a divided by sqrt(1 + lambda) (the same solution): a large
  // lambda then leaves it well conditioned, and its limit, the least-squares affine motion, found.
  const double shrink = 1 / std::sqrt(1 + smoothing);
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n + 3, n + 3), b = Eigen::MatrixXd::Zero(n + 3, 2);
  for (Eigen::Index i = 0; i < n; ++i) {
    const PicturePoint& p = from[size_t(i)];
    for (Eigen::Index j = 0; j < n; ++j) {
      const PicturePoint& q = from[size_t(j)];
      a(i, j) = kernel((std::pow(p[0] - q[0], 2) + std::pow(p[1] - q[1], 2)) / (scale * scale)) *
                shrink * shrink;
    }
    a(i, i) += smoothing * shrink * shrink;
    const double row[3] = {1, p[0] / scale, p[1] / scale};
    for (Eigen::Index k = 0; k < 3; ++k) a(i, n + k) = a(n + k, i) = row[k];
    b(i, 0) = (to[size_t(i)][0] - p[0]) * shrink;
    b(i, 1) = (to[size_t(i)][1] - p[1]) * shrink;
  }
  // The system is singular exactly when the points are collinear (their affine part undetermined).
  if (Eigen::FullPivLU<Eigen::MatrixXd>(a.bottomLeftCorner(3, n)).rank() < 3)
    throw Error("warp: the points are collinear: no spline through them");
  const Eigen::MatrixXd solution = a.colPivHouseholderQr().solve(b);
  for (Eigen::Index i = 0; i < n; ++i)
    weights_.push_back({solution(i, 0) * shrink, solution(i, 1) * shrink});
  for (Eigen::Index k = 0; k < 3; ++k)
    affine_[size_t(k)] = {solution(n + k, 0) / shrink, solution(n + k, 1) / shrink};
}

PicturePoint PictureWarp::operator()(const PicturePoint& p) const {
  const double x = p[0] / scale_, y = p[1] / scale_;
  PicturePoint moved = p;
  for (int k = 0; k < 2; ++k)
    moved[size_t(k)] +=
        affine_[0][size_t(k)] + affine_[1][size_t(k)] * x + affine_[2][size_t(k)] * y;
  for (size_t i = 0; i < centres_.size(); ++i) {
    const double u =
        kernel((std::pow(p[0] - centres_[i][0], 2) + std::pow(p[1] - centres_[i][1], 2)) /
               (scale_ * scale_));
    moved[0] += weights_[i][0] * u;
    moved[1] += weights_[i][1] * u;
  }
  return moved;
}

}  // namespace maquette
