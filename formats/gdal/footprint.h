// Where a source lies on the globe, and how fine its pixels are on the ground.
#pragma once

#include <string>
#include <vector>

#include "core/geojson.h"
#include "core/grid.h"
#include "gdal/raster_source.h"

namespace maquette {

// The source's footprint as lon/lat polygons ready for Grid::cover_polygon (longitudes
// continuous, possibly beyond +-180; a footprint around a pole is closed along the pole), and
// its lon/lat bounds for messages.
struct Footprint {
  std::vector<PolygonRings> polygons;
  double west = 0, south = 0, east = 0, north = 0;
  std::string describe() const;  // "lon W..E, lat S..N"
};

// Densified raster bounds (64 points per edge) transformed to lon/lat. Geographic north-up
// sources are their lon/lat box. Throws maquette::Error naming the file when no edge point
// transforms.
Footprint source_footprint(const RasterSource& source);

// The footprint's part inside `region` (lon/lat polygons; longitudes of either beyond +-180 are
// matched modulo 360), clipped by OGR; west..east and south..north those of the part. What an
// ingest limited to a --bbox or --region covers: covering a global source whole at a fine level
// would count billions of cells for a region of a few.
Footprint clipped_footprint(const Footprint& footprint, const std::vector<PolygonRings>& region);

// Cells at `level` overlapping the footprint, sorted.
std::vector<CellId> cover_footprint(const Grid& grid, const Footprint& footprint, int level);

// The ground size of one source pixel at the raster's centre, in metres: the square root of the
// area of the parallelogram spanned by the pixel's sides on the WGS84 ellipsoid (in earth-centred
// coordinates), so it is right for projected and geographic CRSs alike, and at the poles.
double ground_pixel_m(const RasterSource& source);

}  // namespace maquette
