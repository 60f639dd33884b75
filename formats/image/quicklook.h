// PNG quicklooks of a lon/lat raster: class colours for categorical layers, three chosen channels
// as RGB (imagery), else one channel through a colour ramp, optionally multiplied by a
// hillshade of the layer itself. Values are stretched between the given or the 2-98 % range of
// each drawn channel. No data is transparent.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "image/class_table.h"
#include "image/colour_ramp.h"
#include "image/lonlat_mosaic.h"

namespace maquette {

struct QuicklookStyle {
  Ramp ramp = Ramp::Grey;
  std::optional<std::pair<double, double>> range;  // value mapped to 0 and to 1
  bool hillshade = false;                          // one-channel layers: shade the ramp
  std::vector<int> bands = {};  // 0-based channels drawn as R, G, B (3+ channels; default 0 1 2)
  std::optional<ClassTable> classes = std::nullopt;  // set for categorical layers
};

// Writes an RGBA PNG; throws maquette::Error naming the path when it cannot be written or a
// band is out of range.
void write_quicklook_png(const LonLatRaster& mosaic, const QuicklookStyle& style,
                         const std::string& path);

}  // namespace maquette
