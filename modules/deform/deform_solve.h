// The weighted least squares of paper 002 §3.2: two solves, the control constraints then the
// cross sections with the control vertices fixed, each with Laplace-Beltrami energy rows. Written
// on any vertex set (the base level's height field, or the vertices of a subdivision level whose
// constraints come through the subdivision matrix, Eq. 4: deform_levels.h). The unknowns are
// heights; horizontal positions stay.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <utility>
#include <vector>

#include "height_field.h"
#include "stroke_band.h"

namespace maquette::deform {

// A positional constraint: the surface at `at` should have height `z` (Eq. 3 and 5); of the
// stroke `feature` (its id, for the errors).
struct HeightConstraint {
  SurfacePoint at;
  double z = 0;
  int64_t feature = 0;
};

// A term of a linear row: coefficient * z[vertex].
using Term = std::pair<size_t, double>;

// Positional constraints as rows: row i is sum of terms[starts[i] .. starts[i + 1]) = rhs[i],
// a constraint of the stroke features[i].
struct ConstraintRows {
  std::vector<size_t> starts{0};
  std::vector<Term> terms;
  std::vector<double> rhs;
  std::vector<int64_t> features;

  void add(std::span<const Term> row, double z, int64_t feature);
};

// The energy row of vertex v: fills `out` with its neighbours and their cotangent weights (>= 0;
// the row is z_v - sum w_n z_n / sum w_n = 0 over the neighbours it reads).
using EnergyNeighbours = std::function<void(size_t v, std::vector<Term>& out)>;

// How the normal equations are solved: exactly, by Eigen's SimplicialLDLT; or by Jacobi-
// preconditioned conjugate gradients (conjugate_gradients.h) started from the current heights,
// for heights already close to the answer (a finer level's: the coarser level's solution
// subdivided), to a residual of kConjugateGradientsTolerance of A^T b's norm (measured on the
// three-level edit's benchmark: 85 iterations, heights within 0.2 um of SimplicialLDLT's; 1e-12:
// 62 iterations, 32 um). A system they do not solve in kConjugateGradientsIterations goes to
// SimplicialLDLT. Only the cross sections' solve iterates: the control curve's, small, has its
// strip held across the curve by the light energy rows alone (hundreds of iterations).
enum class LeastSquaresSolver { Cholesky, ConjugateGradients };
inline constexpr double kConjugateGradientsTolerance = 1e-14;
inline constexpr int kConjugateGradientsIterations = 300;

// Deforms the heights `z` to the control rows, then to the section rows with the control
// vertices fixed (two solves, as Hnaidi et al. 2010 and the paper do):
//  1. unknowns: the vertices in the control rows; rows: those (weight 1) and an energy row per
//     unknown, energy_weight * (z_v - sum_n w_vn z_n) = 0, over its neighbours among the unknowns,
//     weights renormalized. The curve constrains the strip of vertices along it only along the
//     curve; across it the energy rows decide, and the terrain around, which the cross sections
//     replace next, must not: with the input's heights in these rows a channel's strip tilts
//     towards its banks (measured: 38 mm RMS on the curve of a 5 m deep channel instead of under
//     1 mm);
//  2. unknowns: the vertices in the section rows that `may_move` (in the strokes' fields of
//     influence: a vertex beyond a band's edge, held only by a tiny barycentric weight of an edge
//     constraint and a light energy row, would otherwise be thrown tens of metres), minus those
//     of step 1; rows: the section rows
//     (fixed vertices moved to the right-hand side; a row without unknowns is dropped) and an
//     energy row per unknown over all its neighbours, those that are not unknowns at their
//     current height (the field of influence's edge meets the terrain around it).
// Each is solved by its normal equations, the first by SimplicialLDLT, the second with `solver`
// (unknowns ordered by vertex index, rows in
// the order given, so the result depends on nothing else; the normal equations are built by
// blocks of unknowns in parallel, each entry summed in a fixed order, and so are the conjugate
// gradients' products: the same bits for any thread count). Vertices that are no
// unknown keep their heights bit for bit.
// Preconditions: every vertex the rows and energy rows read has a finite height.
// Throws maquette::Error if a system is singular or its solution not finite, naming the solve
// (control curve or cross sections) and the feature at fault: that of the first constraint
// reading the height that fails (a column of the system with no coefficient, or a non-finite
// result), "feature 7: constraint 12 of its control curve (numbered along it from 1) reads a
// height that nothing else holds: ...", else every feature of that solve.
void deform_heights(std::vector<double>& z, const ConstraintRows& control,
                    const ConstraintRows& section, const EnergyNeighbours& neighbours,
                    const std::function<bool(size_t)>& may_move, double energy_weight,
                    LeastSquaresSolver solver);

// The base level (SimplicialLDLT): constraints on the height field's triangles, energy rows with
// cotangent_weights; a vertex may move in step 2 when its position lies in one of `bands`.
// Preconditions: every unknown vertex is interior (not on the raster's border), its position is
// filled, and it and its six neighbours have finite heights.
void deform_heights(HeightField& field, const std::vector<HeightConstraint>& control,
                    const std::vector<HeightConstraint>& section,
                    const std::vector<StrokeBand>& bands, double energy_weight);

}  // namespace maquette::deform
