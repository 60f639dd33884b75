// The least squares' errors name the feature and the constraint at fault: systems made singular by
// a constraint reading a height with no coefficient that no other row holds, in the control
// curve's solve (factorized) and in the cross sections' (by conjugate gradients, and factorized).
#include "../deform_solve.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/error.h"

namespace maquette::deform {
namespace {

// No energy rows: every vertex without neighbours.
const EnergyNeighbours kAlone = [](size_t, std::vector<Term>& out) { out.clear(); };

std::string error_of(std::vector<double>& z, const ConstraintRows& control,
                     const ConstraintRows& section, LeastSquaresSolver solver) {
  try {
    deform_heights(
        z, control, section, kAlone, [](size_t) { return true; }, 0.01, solver);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(DeformSolve, SingularControlSolveNamesTheFeatureAndConstraint) {
  ConstraintRows control;
  control.add(std::vector<Term>{{0, 1.0}}, 10, 7);
  control.add(std::vector<Term>{{2, 1.0}}, 3, 9);
  control.add(std::vector<Term>{{1, 0.0}, {2, 1.0}}, 3, 9);  // vertex 1 held by nothing
  std::vector<double> z{0, 0, 0};
  EXPECT_EQ(error_of(z, control, {}, LeastSquaresSolver::Cholesky),
            "feature 9: constraint 2 of its control curve (numbered along it from 1) reads a "
            "height that nothing else holds: the least squares of the control curve is singular "
            "or not finite");
  EXPECT_EQ(z, (std::vector<double>{0, 0, 0}));  // nothing written
}

TEST(DeformSolve, SingularSectionSolveNamesTheFeatureAndConstraint) {
  ConstraintRows control, section;
  control.add(std::vector<Term>{{0, 1.0}}, 10, 7);
  section.add(std::vector<Term>{{0, 0.5}, {1, 0.5}}, 6, 4);
  section.add(std::vector<Term>{{1, 1.0}, {2, 0.0}}, 2, 4);  // vertex 2 held by nothing
  for (const auto solver : {LeastSquaresSolver::ConjugateGradients, LeastSquaresSolver::Cholesky}) {
    std::vector<double> z{0, 0, 0};
    EXPECT_EQ(error_of(z, control, section, solver),
              "feature 4: constraint 2 of its cross sections (numbered along it from 1) reads a "
              "height that nothing else holds: the least squares of the cross sections is "
              "singular or not finite");
    EXPECT_EQ(z, (std::vector<double>{10, 0, 0}));  // the control solve's result only
  }
  // Held, the same system solves: 0.5 * 10 + 0.5 * z1 = 6, z1 + 0 * z2 = 2, z2 = 4.
  section.add(std::vector<Term>{{2, 1.0}}, 4, 4);
  std::vector<double> z{0, 0, 0};
  EXPECT_EQ(error_of(z, control, section, LeastSquaresSolver::Cholesky), "");
  EXPECT_NEAR(z[1], 2, 1e-12);
  EXPECT_NEAR(z[2], 4, 1e-12);
}

}  // namespace
}  // namespace maquette::deform
