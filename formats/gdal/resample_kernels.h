// The resampling kernels behind resample() (resample.h) that work on points: one sample at a
// time, and four at a time with AVX2 (resample_avx2.cpp) with the same bits, falling back to the
// one-sample kernels outside their common case. Internal to formats/gdal.
#pragma once

#include <cstddef>
#include <limits>
#include <span>

#include "gdal/resample.h"

namespace maquette::resample_detail {

inline constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// floor for the window's coordinate range, without a libm call (the hot path).
inline int ifloor(double v) {
  const int i = int(v);
  return i - (v < i);
}

// Bilinear from the 2x2 pixels at (i, j)..(i + 1, j + 1) with fractions fu, fv (window
// pixels), weights renormalised over the valid pixels; NaN when none.
float bilinear_at(const Window& w, int band, int i, int j, double fu, double fv);
// Keys' cubic convolution at window coordinates (x, y); bilinear where a pixel is missing.
float cubic(const Window& w, int band, double x, double y);

// Samples [0, n) of the points (n a multiple of 4), four at a time, where out is NaN: the
// pixel holding the point, bilinear_at, cubic. They need AVX2.
void nearest4(const Window& w, const WindowPoints& p, size_t n, std::span<float> out);
void bilinear4(const Window& w, const WindowPoints& p, size_t n, std::span<float> out);
void cubic4(const Window& w, const WindowPoints& p, size_t n, std::span<float> out);

}  // namespace maquette::resample_detail
