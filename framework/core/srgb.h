// sRGB's transfer function (IEC 61966-2-1): an encoded component in [0, 1] to linear light.
#pragma once

#include <cmath>

namespace maquette {

inline double srgb_to_linear(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

}  // namespace maquette
