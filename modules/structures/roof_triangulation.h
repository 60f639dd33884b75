// The triangles of a flat roof (and floor): GEOS's constrained Delaunay triangulation of the
// footprint polygon, holes kept, without added points.
#pragma once

#include <cstdint>
#include <vector>

#include "footprint.h"

namespace maquette::structures {

// Triangles as indices into the footprint's points numbered ring after ring (outer first),
// counter-clockwise seen from above, covering the footprint exactly (their areas sum to
// Footprint::area). Precondition: `footprint` from make_footprint (valid). Throws InvalidFootprint
// when GEOS fails on it. Thread-safe (one GEOS context per thread).
std::vector<uint32_t> triangulate_footprint(const Footprint& footprint);

}  // namespace maquette::structures
