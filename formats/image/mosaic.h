// A layer resampled onto a picture frame (lon/lat or polar, see picture_frame.h), for quicklooks:
// one picture whatever faces the cells lie on, the whole globe and the polar caps included.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/cell_id.h"
#include "core/grid.h"
#include "image/picture_frame.h"
#include "store/store.h"

namespace maquette {

struct PictureRaster {
  int width = 0, height = 0, channels = 1;
  std::vector<float> values;          // row-major, interleaved channels, NaN = no data
  std::optional<PictureFrame> frame;  // where the pixels lie; none for plots that are no map
  float at(int col, int row, int channel = 0) const {
    return values[(size_t(row) * size_t(width) + size_t(col)) * size_t(channels) + size_t(channel)];
  }
};

struct MosaicSpec {
  std::optional<std::array<double, 4>> bbox;  // clip to this lon/lat box (W S E N)
  Projection projection = Projection::Auto;
  int max_side = 2048;   // pixels on the longer side, at most
  bool bilinear = true;  // else nearest (categorical layers)
};

// Resamples the tiles of `layer` at `cells` (at the layer's level, e.g. from layer_tile_cells)
// onto a frame covering the box (exactly) or else the cells (cropped to the samples holding
// data), reading the coarsest overview level still as fine as the frame's pixels. Bilinear
// sampling reads across tile and face edges; a pixel whose nearest sample is missing is no data.
// Throws maquette::Error for an unknown layer or when there are no cells.
PictureRaster mosaic_layer(const Store& store, const Grid& grid, const std::string& layer,
                           std::vector<CellId> cells, const MosaicSpec& spec);

}  // namespace maquette
