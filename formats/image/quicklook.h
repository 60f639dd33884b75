// PNG quicklooks of a lon/lat raster: one channel through a colour ramp (stretched between the
// given or the 2-98 % range), three channels as RGB; no data is transparent.
#pragma once

#include <optional>
#include <string>
#include <utility>

#include "image/colour_ramp.h"
#include "image/lonlat_mosaic.h"

namespace maquette {

struct QuicklookStyle {
  Ramp ramp = Ramp::Grey;
  std::optional<std::pair<double, double>> range;  // value mapped to 0 and to 1
};

// Writes an RGBA PNG; throws maquette::Error naming the path when it cannot be written.
void write_quicklook_png(const LonLatRaster& mosaic, const QuicklookStyle& style,
                         const std::string& path);

}  // namespace maquette
