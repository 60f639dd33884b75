// Resampling kernels over a source window, nodata-aware (NaN = missing):
// - nearest: the pixel holding the point;
// - bilinear: the 2x2 pixels around it, weights renormalised over the valid ones (NaN when none);
// - cubic: Keys' cubic convolution (a = -0.5, as GDAL) over 4x4 pixels; bilinear where any of
//   them is missing;
// - average: the area-weighted mean of the pixels under the target pixel's footprint (a box of
//   half-sizes hx, hy window pixels, at least one pixel), over the valid ones;
// - mode: the value covering the largest area of that footprint, ties to the smallest value.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "gdal/raster_source.h"

namespace maquette {

enum class Resampling { Nearest, Bilinear, Cubic, Mode, Average };

std::string_view resampling_name(Resampling r);
Resampling parse_resampling(std::string_view name);  // throws maquette::Error

// The source pixel coordinates (pixel centres at i + 0.5) of a tile's samples, row-major; x NaN:
// not to be resampled. hx, hy: each sample's footprint half-sizes in source pixels (area kernels
// only, else empty). The kernels take them into the window's coordinates ((x - x0) / step) as
// they go, rather than in a pass of their own over the tile.
struct WindowPoints {
  std::span<const double> x, y, hx, hy;
};

// For every sample i with a valid x and every band of the window: out[i * bands + band] = the
// kernel's value there, where out is NaN (not filled by an earlier source). The kernel is chosen
// once per call, and the taps and weights once per sample for all bands.
void resample(const Window& w, Resampling r, const WindowPoints& points, std::span<float> out);

}  // namespace maquette
