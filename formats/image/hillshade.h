// Hillshade of a height raster on a lon/lat grid, for quicklooks.
#pragma once

#include <vector>

#include "image/lonlat_mosaic.h"

namespace maquette {

// Lambertian shading of channel 0 (heights in metres) lit from the north-west 45 degrees above
// the horizon: Horn's 3 x 3 gradient with the pixel's true spacing in metres (longitude spacing
// shrinks with cos(latitude)). Values in [0, 1] (flat ground: sin 45 degrees), row-major; a
// missing neighbour counts as the centre sample, a missing centre gives NaN.
std::vector<float> hillshade(const LonLatRaster& heights);

}  // namespace maquette
