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

// Where render_tile writes: M x M pixels (M = tile size << refine), row-major, channels
// interleaved; nullptr: not wanted. Every pixel is written (NaN where the DEM is missing).
struct RenderTargets {
  float* rgb = nullptr;      // 3 per pixel, 0..255
  float* height = nullptr;   // displaced height, metres
  float* normal = nullptr;   // 3 per pixel, unit (x along columns, y up the rows, z up)
  float* classes = nullptr;  // dominant class (NaN: none)
};

// Renders `cell` `refine` levels finer than its input tiles of size `size`. `dem` and every
// raster (model quantities other than height and slope, by name) carry a halo >= kInputHalo.
// Throws naming `context` and the quantity when the model needs a raster that is not given.
void render_tile(const Model& model, const Grid& grid, CellId cell, int size, int refine,
                 const Tile<float>& dem, const std::map<std::string, const Tile<float>*>& rasters,
                 const std::string& context, const RenderTargets& out);

// The same into vectors of its own (every output).
struct Rendered {
  int size = 0;  // M
  std::vector<float> rgb, height, normal, classes;
};
Rendered render_tile(const Model& model, const Grid& grid, CellId cell, int size, int refine,
                     const Tile<float>& dem,
                     const std::map<std::string, const Tile<float>*>& rasters,
                     const std::string& context);

}  // namespace maquette::texture
