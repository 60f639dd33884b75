// Ordinary least squares by column-pivoted Householder QR (deterministic, exact for data on
// the model to rounding).
#pragma once

#include <vector>

namespace maquette::climate {

struct LeastSquares {
  std::vector<double> coefficients;
  std::vector<double> residuals;  // observed - fitted, per row
  double rmse = 0;                // root mean square residual
  double r2 = 0;                  // 1 - SS_res / SS_tot (1 when SS_tot is 0)
  bool full_rank = false;
};

// rows x columns design matrix (row-major) and observations.
LeastSquares least_squares(const std::vector<double>& design, int columns,
                           const std::vector<double>& observed);

}  // namespace maquette::climate
