// The weighted least squares of paper 002 §3.2 on a triangulated height field, at one level
// (the base level: the subdivision matrix of Eq. 4 is the identity; finer levels will write the
// rows through it). The unknowns are heights; horizontal positions stay.
#pragma once

#include <vector>

#include "height_field.h"

namespace maquette::deform {

// A positional constraint: the surface at `at` should have height `z` (Eq. 3 and 5).
struct HeightConstraint {
  SurfacePoint at;
  double z = 0;
};

// Deforms `field` in place to the control constraints, then to the cross-section constraints
// with the control vertices fixed (two solves, as Hnaidi et al. 2010 and the paper do):
//  1. unknowns: the vertices of the triangles holding `control` points; rows: those constraints
//     (weight 1) and an energy row per unknown, energy_weight * (h_v - sum_n w_vn h_n) = 0 with
//     the cotangent weights of cotangent_weights (the discrete Laplace-Beltrami operator, paper
//     §3.2.2) over its neighbours among the unknowns, renormalized. The curve constrains the strip
//     of vertices along it only along the curve; across it the energy rows decide, and the
//     terrain around, which the cross sections replace next, must not: with the input's heights
//     in these rows a channel's strip tilts towards its banks (measured: 38 mm RMS on the curve of
//     a 5 m deep channel instead of under 1 mm);
//  2. unknowns: the vertices of the triangles holding `section` points, minus those of step 1;
//     rows: the section constraints (fixed vertices moved to the right-hand side; a constraint
//     without unknowns is dropped) and an energy row per unknown over all its neighbours, those
//     that are not unknowns at their current height (the field of influence's edge meets the
//     terrain around it).
// Each is solved by its normal equations with Eigen's SimplicialLDLT (unknowns ordered by vertex
// index, rows in the order given, so the result depends on nothing else). Vertices that are no
// unknown keep their heights bit for bit.
// Preconditions: every unknown vertex is interior (not on the raster's border) and it and its six
// neighbours have finite heights. Throws maquette::Error if a system is singular.
void deform_heights(HeightField& field, const std::vector<HeightConstraint>& control,
                    const std::vector<HeightConstraint>& section, double energy_weight);

}  // namespace maquette::deform
