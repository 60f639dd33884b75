#include "core/lonlat_bounds.h"

#include <algorithm>
#include <cmath>

#include "core/region.h"

namespace maquette {

LonLatBounds lonlat_bounds(const Grid& grid, const std::vector<CellId>& cells) {
  const double lon0 = grid.centre(cells.front()).lon;
  double west = 1e9, east = -1e9, south = 90, north = -90;
  const CellId north_pole = grid.cell_from_point({0, 90}, CellId::kMaxLevel);
  const CellId south_pole = grid.cell_from_point({0, -90}, CellId::kMaxLevel);
  // The compacted set has the same outline and far fewer cells.
  for (CellId c : compact(cells)) {
    // A cell around a pole has no boundary point there.
    if (c.contains(north_pole)) north = 90;
    if (c.contains(south_pole)) south = -90;
    for (const LonLat& p : grid.boundary(c, 8)) {
      const double lon = lon0 + std::remainder(p.lon - lon0, 360.0);
      west = std::min(west, lon);
      east = std::max(east, lon);
      south = std::min(south, p.lat);
      north = std::max(north, p.lat);
    }
  }
  // Around a pole every longitude is in (the boundary's points may miss some).
  if (east - west >= 360.0 - 1e-9 || north >= 90 || south <= -90)
    return {-180.0, south, 180.0, north};
  const double shift = 360.0 * std::floor((west + 180.0) / 360.0);
  return {west - shift, south, east - shift, north};
}

}  // namespace maquette
