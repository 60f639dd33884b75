// Resampling kernels over a source window, nodata-aware (NaN = missing):
// - nearest: the pixel holding the point;
// - bilinear: the 2x2 pixels around it, weights renormalised over the valid ones (NaN when none);
// - cubic: Keys' cubic convolution (a = -0.5, as GDAL) over 4x4 pixels; bilinear where any of
//   them is missing;
// - average: the area-weighted mean of the pixels under the target pixel's footprint (a box of
//   half-sizes hx, hy window pixels, at least one pixel), over the valid ones;
// - mode: the value covering the largest area of that footprint, ties to the smallest value.
#pragma once

#include <string>
#include <string_view>

#include "gdal/raster_source.h"

namespace maquette {

enum class Resampling { Nearest, Bilinear, Cubic, Mode, Average };

std::string_view resampling_name(Resampling r);
Resampling parse_resampling(std::string_view name);  // throws maquette::Error

// The value of `band` at window coordinates (x, y) (pixel centres at i + 0.5).
float resample(const Window& w, int band, Resampling r, double x, double y, double hx, double hy);

}  // namespace maquette
