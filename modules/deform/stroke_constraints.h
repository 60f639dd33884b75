// A feature stroke turned into the positional constraints of paper 002 §3.2 on a mosaic's
// height field: the control curve resampled every `step_m` metres (Eq. 3), and the cross section
// placed at each of those points across the curve, oriented by the rotation-minimizing frames of
// the curve's horizontal trace, sampled every `step_m` metres of offset (Eq. 5).
//
// Elevation along the curve: its Z values (linear between vertices), else its profile (linear in
// the distance along the curve, which must cover the curve within 1 % of its length), else the
// DEM under it (draped). A cross-section point at offset o from the curve point p lies o metres
// horizontally along the frame's normal (positive: right of the direction of travel) and its
// target height is z(p) + dz(o): offsets are map widths and dz vertical on any slope.
#pragma once

#include <string>
#include <vector>

#include "deform_solve.h"
#include "height_field.h"
#include "mosaic_frame.h"
#include "stroke.h"
#include "stroke_band.h"

namespace maquette::deform {

struct StrokeConstraints {
  std::vector<HeightConstraint> control, section;
  std::vector<StrokeBand> bands;  // one per stroke added
};

// Appends the constraints of `stroke` and its band to `out`. `field` holds the mosaic's heights
// (positions are not needed). Throws maquette::Error naming `where` and the feature id when a
// constrained point lies off the mosaic (across face seams: off the plane it unfolds, MosaicFrame)
// or on its border samples, or on a triangle any of whose vertices or their neighbours is nodata
// (the least squares would read them), and when a profile does not cover the curve. The points
// are located in parallel; the error is the first failing point's (curve before sections, in
// order along the curve), as one by one.
void add_stroke_constraints(const FeatureStroke& stroke, const MosaicFrame& frame,
                            const HeightField& field, double step_m, const std::string& where,
                            StrokeConstraints& out);

}  // namespace maquette::deform
