// Jacobi-preconditioned conjugate gradients on a sparse symmetric positive definite matrix, its
// products and dot products by fixed blocks in parallel (TBB), each block's partial sum kept and
// the partials added in block order: the same bits for any thread count. For the finer levels of
// deform.features (deform_solve.h), whose subdivided coarser solution is close to the answer.
#pragma once

#include <Eigen/Sparse>
#include <optional>

namespace maquette::deform {

// Solves m x = b from x's initial value, stopping at the first iterate whose (recurred) residual
// ||b - m x|| <= relative_tolerance * ||b|| (x itself when it already is); returns the number of
// iterations, or nothing when max_iterations did not reach it (x then holds the last iterate).
// Preconditions: m square, symmetric with both triangles stored (compressed columns); b and x of
// its size; relative_tolerance > 0. Throws maquette::Error when m is not positive definite as
// seen by the iterations (a diagonal entry or a curvature p^T m p not > 0).
std::optional<int> conjugate_gradients(const Eigen::SparseMatrix<double>& m,
                                       const Eigen::VectorXd& b, Eigen::VectorXd& x,
                                       double relative_tolerance, int max_iterations);

}  // namespace maquette::deform
