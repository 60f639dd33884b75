// A layer's tiles as one GeoTIFF in the rHEALPix plane: tile samples are north-up squares of
// the plane, so each tile is written bit for bit at its plane position; the raster covers the
// plane squares of all the cells (across faces too), nodata between them.
#pragma once

#include <string>
#include <vector>

#include "core/grid.h"
#include "store/store.h"

namespace maquette {

// Writes the tiles of `cells` (all at `level`: the layer's level, or a coarser one whose
// overview tiles are read) to a tiled, compressed GeoTIFF at `path` with the layer's metadata.
// Throws maquette::Error when none of the cells has a tile or GDAL fails.
void write_plane_geotiff(const Store& store, const Grid& grid, const LayerInfo& layer,
                         const std::vector<CellId>& cells, int level, const std::string& path);

}  // namespace maquette
