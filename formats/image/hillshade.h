// Hillshade of a height raster on a picture frame, for quicklooks.
#pragma once

#include <vector>

#include "image/mosaic.h"

namespace maquette {

// Lambertian shading of channel 0 (heights in metres) lit from the north-west 45 degrees above
// the horizon: Horn's 3 x 3 gradient with the pixel's true spacing in metres (in lon/lat frames
// longitude spacing shrinks with cos(latitude)); `heights` must have a frame. Values in [0, 1]
// (flat ground: sin 45 degrees), row-major; a missing neighbour counts as the centre sample, a
// missing centre gives NaN.
std::vector<float> hillshade(const PictureRaster& heights);

}  // namespace maquette
