// The cells a geometry touches at a level: the index entries of a feature.
#pragma once

#include <ogr_geometry.h>

#include <vector>

#include "core/grid.h"

namespace maquette {

// Cells at `level` touched by `lonlat` (a geometry in WGS84 lon/lat), sorted and unique:
// - points: the cell holding each point;
// - lines: the cells of points sampled along every segment (straight in lon/lat, the short
//   way round in longitude) at a quarter of the mean cell side, and where two consecutive
//   samples fall in cells sharing only a corner, the cells sharing that corner with both
//   (the segment may cut through either), so the set is conservative;
// - polygons: Grid::cover_polygon with Containment::Overlap (every cell meeting the polygon);
// - collections: the union of their parts; curves are linearised first.
// Throws maquette::Error for a geometry type without area, line or point parts (TIN,
// polyhedral surface) or coordinates the grid refuses (latitude outside +-90).
std::vector<CellId> geometry_cells(const Grid& grid, const OGRGeometry& lonlat, int level);

// Approximate ground distance in metres (equirectangular on a sphere, the short way round in
// longitude): for choosing sample spacings and levels, not for measuring.
double approx_distance_m(LonLat a, LonLat b);

}  // namespace maquette
