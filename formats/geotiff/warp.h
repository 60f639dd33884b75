// A layer resampled to a GeoTIFF in another CRS: every output pixel is sampled at its centre's
// lon/lat through the grid (the tile holding it, with a halo across tile and face edges), so
// pixels along face seams read both sides of the seam, whichever faces meet there.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/grid.h"
#include "geotiff/export_crs.h"
#include "store/store.h"

namespace maquette {

struct WarpSpec {
  const OGRSpatialReference* crs = nullptr;
  double resolution = 0;                      // target units per pixel
  bool nearest = true;                        // else bilinear
  std::optional<std::array<double, 4>> bbox;  // lon/lat W S E N: the output covers it
};

// The output's pixels: top-left corner and pixel side in the CRS's units, size in pixels.
struct WarpGrid {
  double left = 0, top = 0, pixel = 0;
  int width = 0, height = 0;
};

// The pixels covering the box, or else the cells' lon/lat bounds (up to the poles they hold),
// transformed to the CRS with densified edges, on pixels of spec.resolution from the top-left
// corner (as gdalwarp -te -tr). Throws maquette::Error when the box cannot be transformed or the
// raster would exceed GeoTIFF's limits.
WarpGrid warp_grid(const Grid& grid, const std::vector<CellId>& cells, const WarpSpec& spec);

// Writes the tiles of `cells` (all at `level`: the layer's level, or a coarser one whose overview
// tiles are read) onto `pixels` to a tiled, compressed GeoTIFF at `path` in `spec.crs`, with the
// layer's metadata. Pixels whose centres lie outside the box, outside the cells or outside the
// CRS's domain are nodata. Nearest sampling gives each pixel the sample of the cell holding its
// centre. Throws maquette::Error when none of the cells has a tile or GDAL fails.
void write_warped_geotiff(const Store& store, const Grid& grid, const LayerInfo& layer,
                          const std::vector<CellId>& cells, int level, const WarpSpec& spec,
                          const WarpGrid& pixels, const std::string& path);

}  // namespace maquette
