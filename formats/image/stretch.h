// The display stretch of imagery, shared by PNG quicklooks and 3D Tiles textures: each band's
// 2nd and 98th percentiles are shown as black and white.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <utility>
#include <vector>

#include "core/round_half_away.h"

namespace maquette {

using StretchRange = std::pair<double, double>;  // values shown as 0 and as 255

inline constexpr std::pair<double, double> kDisplayStretch = {0.02, 0.98};  // quantiles

// The q0 and q1 quantiles of the finite values (those of ranks q * (count - 1), as std::nth_element
// selects them), hi > lo; (0, 1) when there is none.
StretchRange quantile_range(std::span<const float> values, double q0, double q1);

// The same quantiles of each of `bands` bands of `values`, interleaved (value i of band
// i % bands; the size a multiple of bands).
std::vector<StretchRange> quantile_ranges(std::span<const float> values, size_t bands, double q0,
                                          double q1);

// Values in chunks, read where they are (a picture's texels among its other pixels): chunk c's
// values, the same at every call, in `buffer` (given cleared, one per thread) or elsewhere.
using ValueChunk = std::function<std::span<const float>(size_t c, std::vector<float>& buffer)>;

// The same of the values of `chunks` chunks, each band interleaved (each chunk's size a multiple
// of bands).
std::vector<StretchRange> quantile_ranges(size_t chunks, size_t bands, const ValueChunk& chunk,
                                          double q0, double q1);

// A value stretched to a byte: `range` mapped to 0..255, clamped. Inline: the panorama stretches
// three bands a pixel.
inline uint8_t stretch_byte(double value, const StretchRange& range) {
  const double t = (value - range.first) / (range.second - range.first);
  return uint8_t(round_half_away(255.0 * std::clamp(t, 0.0, 1.0)));
}

}  // namespace maquette
