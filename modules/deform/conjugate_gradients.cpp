#include "conjugate_gradients.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <vector>

#include "core/error.h"

namespace maquette::deform {
namespace {

// Entries per block: the unit of parallel work and of the partial sums, fixed so that the sums'
// order does not depend on the threads.
constexpr Eigen::Index kBlock = 4096;

// Runs body(begin, end) on the blocks of [0, n) in parallel; returns the sums of the two values
// it returns, the blocks' partials added in block order.
template <typename Body>
std::array<double, 2> block_sums(Eigen::Index n, const Body& body) {
  std::vector<std::array<double, 2>> partial(size_t((n + kBlock - 1) / kBlock));
  tbb::parallel_for(size_t(0), partial.size(), [&](size_t k) {
    const Eigen::Index begin = Eigen::Index(k) * kBlock;
    partial[k] = body(begin, std::min(n, begin + kBlock));
  });
  std::array<double, 2> sum{0, 0};
  for (const auto& [a, b] : partial) sum = {sum[0] + a, sum[1] + b};
  return sum;
}

}  // namespace

std::optional<int> conjugate_gradients(const Eigen::SparseMatrix<double>& m,
                                       const Eigen::VectorXd& b, Eigen::VectorXd& x,
                                       double relative_tolerance, int max_iterations) {
  const Eigen::Index n = m.cols();
  const int* outer = m.outerIndexPtr();
  const int* inner = m.innerIndexPtr();
  const double* value = m.valuePtr();
  // q[j] = (m v)[j]: m is symmetric, so row j is column j.
  Eigen::VectorXd inverse_diagonal(n), r(n), z(n), p(n), q(n);
  const auto product = [&](const Eigen::VectorXd& v, Eigen::Index j) {
    double s = 0;
    for (int e = outer[j]; e < outer[j + 1]; ++e) s += value[e] * v[inner[e]];
    q[j] = s;
  };
  // r = b - m x, z = r / diag(m), p = z; sums r.z and r.r.
  auto [rz, r2] = block_sums(n, [&](Eigen::Index begin, Eigen::Index end) {
    double rz_part = 0, r2_part = 0;
    for (Eigen::Index j = begin; j < end; ++j) {
      double d = 0;
      for (int e = outer[j]; e < outer[j + 1]; ++e)
        if (inner[e] == j) d = value[e];
      if (!(d > 0)) throw Error("conjugate gradients: a diagonal entry is not positive");
      inverse_diagonal[j] = 1 / d;
      product(x, j);
      r[j] = b[j] - q[j];
      z[j] = r[j] * inverse_diagonal[j];
      p[j] = z[j];
      rz_part += r[j] * z[j];
      r2_part += r[j] * r[j];
    }
    return std::array{rz_part, r2_part};
  });
  const double b2 = block_sums(n, [&](Eigen::Index begin, Eigen::Index end) {
    double s = 0;
    for (Eigen::Index j = begin; j < end; ++j) s += b[j] * b[j];
    return std::array{s, 0.0};
  })[0];
  const double limit2 = relative_tolerance * relative_tolerance * b2;
  for (int iteration = 0;; ++iteration) {
    if (r2 <= limit2) return iteration;
    if (iteration == max_iterations) return std::nullopt;
    const double pq = block_sums(n, [&](Eigen::Index begin, Eigen::Index end) {
      double s = 0;
      for (Eigen::Index j = begin; j < end; ++j) {
        product(p, j);
        s += p[j] * q[j];
      }
      return std::array{s, 0.0};
    })[0];
    if (!(pq > 0)) throw Error("conjugate gradients: the matrix is not positive definite");
    const double alpha = rz / pq;
    const auto [rz_next, r2_next] = block_sums(n, [&](Eigen::Index begin, Eigen::Index end) {
      double rz_part = 0, r2_part = 0;
      for (Eigen::Index j = begin; j < end; ++j) {
        x[j] += alpha * p[j];
        r[j] -= alpha * q[j];
        z[j] = r[j] * inverse_diagonal[j];
        rz_part += r[j] * z[j];
        r2_part += r[j] * r[j];
      }
      return std::array{rz_part, r2_part};
    });
    const double beta = rz_next / rz;
    rz = rz_next;
    r2 = r2_next;
    tbb::parallel_for(Eigen::Index(0), n, kBlock, [&](Eigen::Index begin) {
      for (Eigen::Index j = begin; j < std::min(n, begin + kBlock); ++j) p[j] = z[j] + beta * p[j];
    });
  }
}

}  // namespace maquette::deform
