// Where points equally spaced along a segment of the tangent plane lie on a mosaic, as
// MosaicFrame::local_sample puts each, for a fraction of the cost: the
// cross sections of deform.features are such lines, hundreds of thousands of points a step.
#pragma once

#include <array>
#include <span>

#include "mosaic_frame.h"

namespace maquette::deform {

// Within this many samples of each point's own coordinates: far above the quadratic's error on
// lines of tens of metres, far below anything a height sees (DeformSeams.
// LinesOfPointsLocatedAsEachPointAlone checks the points against their own, within it).
inline constexpr double kLineTolerance = 1e-7;

// Fills out[j] with the fractional sample coordinates of points[j] (NaN where the frame has no
// place for it), the points equally spaced along a segment. Of 5 points or more, the first,
// middle and last are computed, and the quadratic through them (in the point's index, taken of
// the face pixels of the unfolded plane, MosaicFrame::origin, so that neither the coordinates
// nor the choice below depend on where the mosaic starts) gives the others when it gives the
// points at a quarter and three quarters along within kLineTolerance of their own coordinates,
// computed too; else every point is computed: the map from the tangent plane to the samples is
// smooth but where a line crosses a face seam or the edge of a polar cap, where it has a kink.
// Returns whether the quadratic was used. Precondition: out has the size of points.
bool line_samples(const MosaicFrame& frame, std::span<const EastNorth2> points,
                  std::span<std::array<double, 2>> out);

}  // namespace maquette::deform
