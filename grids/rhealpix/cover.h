// Covering lon/lat regions with cells by hierarchical refinement from the six faces: a cell
// whose lon/lat bounding rectangle is inside the region contributes all its descendants, one
// disjoint from it none, and only cells crossing the region's boundary are split.
#pragma once

#include <functional>
#include <span>
#include <vector>

#include "core/grid.h"
#include "lonlat_polygon.h"
#include "projection.h"

namespace maquette {

// The smallest lon/lat rectangle holding the cell (exact: the cell's extreme longitudes and
// latitudes are at its corners or, for the latitude nearest a pole, on its edges). West is in
// [-180, 180); a cell around a pole spans all longitudes.
LonLatRect cell_rect(const RHealpixProjection& projection, CellId cell);

// Cells at `level` sorted by id. Centre mode is exact, and so are Overlap and Full wherever
// cells are lon/lat rectangles (equatorial faces, cells at a pole); other polar cells crossing
// the region's boundary are tested by their boundary, inset by 1e-5 and densified to 1e-3 of
// the cell's width (see inset_ring in cover.cpp): they may be misjudged only when the region's
// boundary passes that close to theirs.
std::vector<CellId> cover(const RHealpixProjection& projection, const LonLatPolygon& region,
                          int level, Containment mode);
// The cover of the union of `regions`, visited in id order without being held: a cell coarser
// than `level` stands for all its descendants at `level` (it lies inside a region); each cell at
// `level` is visited once, in one of these or as itself.
void visit_cover(const RHealpixProjection& projection, std::span<const LonLatPolygon> regions,
                 int level, Containment mode, const std::function<void(CellId)>& visit);

}  // namespace maquette
