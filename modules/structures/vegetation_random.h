// The paper's placement of plants (§5, after Deussen et al. [28]), kept as
// `"placement": "random"` to compare with the blue noise of poisson_disk.h: the region is
// triangulated (constrained Delaunay: roof_triangulation.h), and round(area / spacing^2) plants
// each fall in a triangle drawn with probability proportional to its area, uniformly within it.
// Nothing keeps plants apart: as in a Poisson process of density 1 / spacing^2, a fraction
// 1 - exp(-pi / 4) (54 %) of them have a neighbour closer than half the spacing.
#pragma once

#include <cstdint>
#include <vector>

#include "core/grid.h"
#include "footprint.h"

namespace maquette::structures {

// The plants of a polygon (a stroke's part in its plane, metres, from make_footprint, which
// refuses crossing rings) from hashes of (seed, index): the same points for the same polygon and
// seed, whoever asks. Precondition: spacing > 0.
std::vector<PlanePoint> random_placement(const Footprint& polygon, double spacing, uint64_t seed);

}  // namespace maquette::structures
