// deform.features at finer levels (paper 002 §3.2, Eq. 1-4; the step's "refine": k): the
// deformed surface k times subdivided near the features, as a patch of the finer raster.
#pragma once

#include <vector>

#include "deform_solve.h"
#include "stroke_constraints.h"

namespace maquette::deform {

// The samples (inclusive) of the base field that the subdivision works on: the constrained
// triangles' vertices (of every level's constraints) grown by kRefineMargin + levels samples,
// clamped to the field (deform.features refuses constraints nearer its edge: the window never
// meets Loop's border masks). The horizontal positions of its samples with data must be filled
// before refined_heights.
struct SampleWindow {
  int col0 = 0, row0 = 0, col1 = 0, row1 = 0;
};
// The refined zone: the constrained triangles grown by kZoneRings samples; the window: one ring
// more, which Loop's masks of the zone's vertices read, and a ring per level (the zone's finer
// vertices reach one coarser ring further at each level).
inline constexpr int kZoneRings = 2, kRefineMargin = kZoneRings + 1;
SampleWindow refinement_window(const HeightField& field,
                               const std::vector<StrokeConstraints>& by_level);

// Heights of the finer raster's pixels (col0 + j, row0 + i), row-major, columns x rows. Pixel
// (J, I) of the raster `levels` times finer (side field.width << levels) has its centre at
// fractional base sample coordinates ((J + 0.5) / 2^levels - 0.5, (I + 0.5) / 2^levels - 0.5).
struct RefinedPatch {
  int col0 = 0, row0 = 0, columns = 0, rows = 0;
  std::vector<double> z;
};

// Adaptive: Loop near the features only; Uniform: every triangle of the window (the adaptive
// subdivision's oracle: the same heights inside the refined zone).
enum class Subdivision { Adaptive, Uniform };

// The window's samples as the base mesh of adaptive Loop subdivision (loop_adaptive.h), refined
// levels = by_level.size() times around the triangles holding constraints grown by kZoneRings
// samples, neighbours at most one level apart, or every triangle of the window
// (Subdivision::Uniform). The growth keeps the vertices every level solves, and those their
// energy rows read, in refined triangles: the systems are uniform subdivision's, and so are the
// heights there (measured: the same bits; with the constrained triangles alone, 8.5 cm apart). Per
// level t = 0 .. levels - 1: each constraint of by_level[t] (the strokes sampled as densely as the
// level-t vertices need: add_stroke_constraints every half a level-t sample) is located on the
// level-(t+1) surface (its triangle on the level's grid, barycentric weights alpha, beta, gamma)
// and written on the level-t vertices through the subdivision matrix, alpha S_a + beta S_b + gamma
// S_c (Eq. 4); the two solves of deform_heights give the level-t heights (energy rows: cotangent
// weights of the level-t mesh's horizontal positions, negative cotangents taken as 0); the heights
// are subdivided to t + 1. The finest mesh is sampled at the finer pixel centres of the window (a
// centre on an edge takes the first triangle's value: the mesh is conforming, both agree). Away
// from the refined zone the mesh's triangles are the input's, so the patch is the input linearly
// interpolated there (height_at_clamped), as outside the window. Preconditions: levels >= 1; the
// window's horizontal positions filled; those of deform_heights on each level (finite heights
// around the constraints). Throws maquette::Error as it does.
RefinedPatch refined_heights(const HeightField& field, const SampleWindow& window,
                             const std::vector<StrokeConstraints>& by_level, double energy_weight,
                             Subdivision subdivision);

}  // namespace maquette::deform
