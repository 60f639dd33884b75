// The display stretch of imagery, shared by PNG quicklooks and 3D Tiles textures: each band's
// 2nd and 98th percentiles are shown as black and white.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

namespace maquette {

using StretchRange = std::pair<double, double>;  // values shown as 0 and as 255

inline constexpr std::pair<double, double> kDisplayStretch = {0.02, 0.98};  // quantiles

// The q0 and q1 quantiles of the finite values (which it reorders), hi > lo; (0, 1) when there
// is none.
StretchRange quantile_range(std::vector<float>& values, double q0, double q1);

// A value stretched to a byte: `range` mapped to 0..255, clamped.
uint8_t stretch_byte(double value, const StretchRange& range);

}  // namespace maquette
