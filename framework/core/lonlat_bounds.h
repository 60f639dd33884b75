// Longitude/latitude bounds of a set of cells.
#pragma once

#include <vector>

#include "core/grid.h"

namespace maquette {

struct LonLatBounds {
  double west = 0, south = 0, east = 0, north = 0;  // degrees; see lonlat_bounds
};

// Bounds of the cells' boundaries. Longitudes are unwrapped around the first cell, so a set of
// cells across the antimeridian stays in one piece: west is in [-180, 180) and east may exceed
// 180 (east - 360 is then the eastern edge). Cells around a pole span all longitudes and reach
// the pole.
// `cells` must not be empty.
LonLatBounds lonlat_bounds(const Grid& grid, const std::vector<CellId>& cells);

}  // namespace maquette
