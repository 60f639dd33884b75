// sRGB's transfer function (IEC 61966-2-1): an encoded component in [0, 1] to linear light, and
// linear light back to the nearest 8-bit code.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace maquette {

inline double srgb_to_linear(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// Linear light (clamped to [0, 1]) to an sRGB-encoded value, 0..255 (not rounded).
inline double srgb_from_linear(double linear) {
  const double l = std::clamp(linear, 0.0, 1.0);
  return 255 * (l <= 0.0031308 ? 12.92 * l : 1.055 * std::pow(l, 1 / 2.4) - 0.055);
}

// Linear light (clamped to [0, 1]) to the nearest 8-bit sRGB code.
inline uint8_t linear_to_srgb_byte(double linear) {
  return uint8_t(std::lround(srgb_from_linear(linear)));
}

}  // namespace maquette
