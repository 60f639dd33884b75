// A layer's tiles as one GeoTIFF in the rHEALPix plane: tile samples are north-up squares of
// the plane, so each tile is written bit for bit at its plane position; the raster covers the
// plane squares of all the cells (across faces too), nodata between them, or only the part of
// them a lon/lat box covers.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/grid.h"
#include "store/store.h"

namespace maquette {

// Where a plane GeoTIFF lies: top-left corner and pixel side (metres), size in pixels.
struct PlaneExtent {
  double x_min = 0, y_max = 0, pixel = 0;
  int64_t width = 0, height = 0;
};

// The plane squares of `cells` (all at one level, tiles of `tile_size` samples), cut down to the
// plane bounds of `bbox` (W S E N degrees) when given, on whole pixels of the tiles.
PlaneExtent plane_extent(const Grid& grid, const std::vector<CellId>& cells, int tile_size,
                         const std::optional<std::array<double, 4>>& bbox);

// Writes the tiles of `cells` (all at `level`: the layer's level, or a coarser one whose
// overview tiles are read), each cut to `extent`, to a tiled, compressed GeoTIFF at `path` with
// the layer's metadata; with a box, samples outside it are nodata (when the layer has one). Throws
// maquette::Error when none of the cells has a tile or GDAL fails.
void write_plane_geotiff(const Store& store, const Grid& grid, const LayerInfo& layer,
                         const std::vector<CellId>& cells, int level, const PlaneExtent& extent,
                         const std::optional<std::array<double, 4>>& bbox, const std::string& path);

}  // namespace maquette
