// A layer resampled (nearest sample) onto a regular longitude/latitude raster covering its
// cells, for quicklooks: one picture whatever faces the cells lie on.
#pragma once

#include <string>
#include <vector>

#include "core/cell_id.h"
#include "core/grid.h"
#include "store/store.h"

namespace maquette {

struct LonLatRaster {
  int width = 0, height = 0, channels = 1;
  double west = 0, north = 0, step = 0;  // degrees: top-left corner and pixel size
  std::vector<float> values;             // row-major, interleaved channels, NaN = no data
  float at(int col, int row, int channel = 0) const {
    return values[(size_t(row) * size_t(width) + size_t(col)) * size_t(channels) + size_t(channel)];
  }
};

// Resamples the tiles of `layer` at `cells` (cells at the layer's level, e.g. from
// layer_tile_cells; all its tiles when empty) onto a lon/lat raster no larger than
// `max_side` pixels on its longer side, reading overview levels when that is coarser than the
// layer, cropped to the samples holding data. Throws maquette::Error for an unknown layer or
// when there are no tiles.
LonLatRaster mosaic_layer(const Store& store, const Grid& grid, const std::string& layer,
                          std::vector<CellId> cells, int max_side = 2048);

}  // namespace maquette
