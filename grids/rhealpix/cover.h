// Covering lon/lat regions with cells by hierarchical refinement from the six faces: a cell
// whose lon/lat bounding rectangle is inside the region contributes all its descendants, one
// disjoint from it none, and only cells crossing the region's boundary are split.
#pragma once

#include <vector>

#include "core/grid.h"
#include "lonlat_polygon.h"
#include "projection.h"

namespace maquette {

// The smallest lon/lat rectangle holding the cell (exact: the cell's extreme longitudes and
// latitudes are at its corners or, for the latitude nearest a pole, on its edges). West is in
// [-180, 180); a cell around a pole spans all longitudes.
LonLatRect cell_rect(const RHealpixProjection& projection, CellId cell);

// Cells at `level` sorted by id. Centre mode is exact; on equatorial faces, where cells are
// lon/lat rectangles, so are the others; on polar faces a cell crossing the region's boundary
// is tested by its bounding rectangle: Overlap may then add, and Full omit, a few boundary cells.
std::vector<CellId> cover(const RHealpixProjection& projection, const LonLatPolygon& region,
                          int level, Containment mode);

}  // namespace maquette
