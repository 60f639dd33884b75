#include "regression.h"

#include <Eigen/Dense>
#include <cmath>

namespace maquette::climate {

LeastSquares least_squares(const std::vector<double>& design, int columns,
                           const std::vector<double>& observed) {
  const Eigen::Index rows = Eigen::Index(observed.size());
  const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> a(
      design.data(), rows, columns);
  const Eigen::Map<const Eigen::VectorXd> b(observed.data(), rows);
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
  LeastSquares out;
  out.full_rank = qr.rank() == columns;
  if (!out.full_rank) return out;
  const Eigen::VectorXd x = qr.solve(b);
  const Eigen::VectorXd r = b - a * x;
  out.coefficients.assign(x.data(), x.data() + columns);
  out.residuals.assign(r.data(), r.data() + rows);
  const double mean = b.mean();
  const double ss_tot = (b.array() - mean).square().sum(), ss_res = r.squaredNorm();
  out.rmse = std::sqrt(ss_res / double(rows));
  out.r2 = ss_tot > 0 ? 1 - ss_res / ss_tot : 1;
  return out;
}

}  // namespace maquette::climate
