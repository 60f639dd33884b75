// The display stretch of imagery, shared by PNG quicklooks and 3D Tiles textures: each band's
// 2nd and 98th percentiles are shown as black and white.
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <utility>

#include "core/round_half_away.h"

namespace maquette {

using StretchRange = std::pair<double, double>;  // values shown as 0 and as 255

inline constexpr std::pair<double, double> kDisplayStretch = {0.02, 0.98};  // quantiles

// The q0 and q1 quantiles of the finite values (those of ranks q * (count - 1), as std::nth_element
// selects them), hi > lo; (0, 1) when there is none.
StretchRange quantile_range(std::span<const float> values, double q0, double q1);

// A value stretched to a byte: `range` mapped to 0..255, clamped. Inline: the panorama stretches
// three bands a pixel.
inline uint8_t stretch_byte(double value, const StretchRange& range) {
  const double t = (value - range.first) / (range.second - range.first);
  return uint8_t(round_half_away(255.0 * std::clamp(t, 0.0, 1.0)));
}

}  // namespace maquette
