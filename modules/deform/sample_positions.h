// The horizontal positions of a mosaic's samples (metres east and north in the tangent plane of
// MosaicFrame, at the grid's pixel centres), for the cotangent weights and bands of
// deform.features: tens of thousands a step, each a projection and a geodetic conversion.
#pragma once

#include <vector>

#include "height_field.h"
#include "mosaic_frame.h"

namespace maquette::deform {

// Within this many metres of each sample's own position (DeformSeams.
// SamplePositionsAsEachSampleAlone checks the positions against the grid's pixel centres).
inline constexpr double kPositionTolerance = 1e-7;

// Fills field.east and field.north of every sample v with wanted[v] (row-major as the field)
// whose east is NaN. Along each row the samples are taken by stretches of 32 face pixels of the
// plane unfolded around the mosaic's face (MosaicFrame::origin: the same stretches for every
// mosaic of that plane, so a position does not depend on where the mosaic starts, nor on which
// others are asked): the positions of a stretch's ends and middle are computed, and the
// quadratic through them gives its other samples' when it gives those a quarter and three
// quarters along within kPositionTolerance of their own, computed too; else each is computed
// (across a face seam or the edge of a polar cap, where the map has a kink, or a stretch reaching
// a gap of the plane). Rows in parallel: a row that fails throws the error of the first failing
// row, as the serial loop would. Precondition: no wanted sample lies in a gap of the
// plane (MosaicFrame::sample_lonlat throws maquette::Error for one; deform.features asks only
// samples with data).
void place_samples(const MosaicFrame& frame, const std::vector<char>& wanted, HeightField& field);

}  // namespace maquette::deform
