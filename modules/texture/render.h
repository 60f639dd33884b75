// One tile of the procedural texture: the inputs upsampled to the target resolution
// (field.h), the model evaluated (surface.h), and the interior cut out.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/grid.h"
#include "core/tile.h"
#include "model.h"

namespace maquette::texture {

struct Rendered {
  int size = 0;                // M = tile size << refine
  std::vector<float> rgb;      // 3 per pixel, 0..255, NaN where the DEM is missing
  std::vector<float> height;   // displaced height, metres
  std::vector<float> normal;   // 3 per pixel, unit (x along columns, y up the rows, z up)
  std::vector<float> classes;  // dominant class (NaN: none)
};

// Renders `cell` `refine` levels finer than its input tiles of size `size`. `dem` and every
// raster (model quantities other than height and slope, by name) carry a halo >= kInputHalo.
// Throws naming `context` and the quantity when the model needs a raster that is not given.
Rendered render_tile(const Model& model, const Grid& grid, CellId cell, int size, int refine,
                     const Tile<float>& dem,
                     const std::map<std::string, const Tile<float>*>& rasters,
                     const std::string& context);

}  // namespace maquette::texture
