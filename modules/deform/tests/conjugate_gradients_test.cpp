// conjugate_gradients (conjugate_gradients.h) on a system with a known solution: the 1D
// screened Poisson matrix tridiag(-1, 2 + s, -1) (symmetric positive definite), b = m x* for an
// x* chosen; against x* and Eigen's SimplicialLDLT, from a cold and a warm start, the same bits
// on one thread and several, and the limits of its contract.
#include "../conjugate_gradients.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include "core/error.h"

namespace maquette::deform {
namespace {

constexpr int kSize = 20000;

Eigen::SparseMatrix<double> screened_poisson(int n, double s, double diagonal_scale = 1) {
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < n; ++i) {
    entries.emplace_back(i, i, (2 + s) * diagonal_scale);
    if (i > 0) entries.emplace_back(i, i - 1, -1.0);
    if (i + 1 < n) entries.emplace_back(i, i + 1, -1.0);
  }
  Eigen::SparseMatrix<double> m(n, n);
  m.setFromTriplets(entries.begin(), entries.end());
  return m;
}

// Heights of a terrain-like profile: 1500 m and a few metres of waves.
Eigen::VectorXd profile(int n) {
  Eigen::VectorXd x(n);
  for (int i = 0; i < n; ++i) x[i] = 1500 + 3 * std::sin(i * 0.01) + 0.5 * std::cos(i * 0.37);
  return x;
}

TEST(ConjugateGradients, SolvesTheScreenedPoissonSystem) {
  const Eigen::SparseMatrix<double> m = screened_poisson(kSize, 0.05);
  const Eigen::VectorXd expected = profile(kSize), b = m * expected;
  Eigen::VectorXd cold = Eigen::VectorXd::Zero(kSize);
  const std::optional<int> iterations = conjugate_gradients(m, b, cold, 1e-14, 1000);
  ASSERT_TRUE(iterations);
  EXPECT_GT(*iterations, 10);
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(m);
  const Eigen::VectorXd exact = ldlt.solve(b);
  EXPECT_LT((cold - expected).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT((cold - exact).cwiseAbs().maxCoeff(), 1e-9);

  // Warm: started 1 cm off everywhere, as a subdivided coarser level is, it needs fewer iterations.
  Eigen::VectorXd warm = expected + Eigen::VectorXd::Constant(kSize, 0.01);
  const std::optional<int> warm_iterations = conjugate_gradients(m, b, warm, 1e-14, 1000);
  ASSERT_TRUE(warm_iterations);
  EXPECT_LT(*warm_iterations, *iterations);
  EXPECT_LT((warm - expected).cwiseAbs().maxCoeff(), 1e-9);
  std::printf("cold start: %d iterations, warm: %d\n", *iterations, *warm_iterations);
}

TEST(ConjugateGradients, SameBitsForOneThreadAndMore) {
  const Eigen::SparseMatrix<double> m = screened_poisson(kSize, 0.05);
  const Eigen::VectorXd b = m * profile(kSize);
  Eigen::VectorXd one = Eigen::VectorXd::Zero(kSize), many = one;
  {
    const tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    ASSERT_TRUE(conjugate_gradients(m, b, one, 1e-14, 1000));
  }
  ASSERT_TRUE(conjugate_gradients(m, b, many, 1e-14, 1000));
  EXPECT_EQ(std::memcmp(one.data(), many.data(), sizeof(double) * kSize), 0);
}

TEST(ConjugateGradients, StartAlreadySolvedTakesNoIteration) {
  const Eigen::SparseMatrix<double> m = screened_poisson(100, 1);
  const Eigen::VectorXd x0 = Eigen::VectorXd::LinSpaced(100, 0, 1);
  Eigen::VectorXd x = x0;
  EXPECT_EQ(conjugate_gradients(m, m * x0, x, 1e-12, 10), 0);
  EXPECT_EQ(x, x0);
}

TEST(ConjugateGradients, TooFewIterationsReturnNothing) {
  const Eigen::SparseMatrix<double> m = screened_poisson(kSize, 1e-6);
  const Eigen::VectorXd b = m * profile(kSize);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(kSize);
  EXPECT_FALSE(conjugate_gradients(m, b, x, 1e-14, 5));
}

TEST(ConjugateGradients, NonPositiveMatrixIsAnError) {
  const Eigen::SparseMatrix<double> m = screened_poisson(100, 0, -1);  // negative diagonal
  Eigen::VectorXd x = Eigen::VectorXd::Zero(100);
  EXPECT_THROW(conjugate_gradients(m, Eigen::VectorXd::Ones(100), x, 1e-12, 100), Error);
}

}  // namespace
}  // namespace maquette::deform
