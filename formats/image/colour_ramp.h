// Colour ramps for quicklooks: values to 8-bit RGB.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

namespace maquette {

enum class Ramp { Grey, Terrain, Slope };
Ramp parse_ramp(std::string_view name);  // "grey", "terrain", "slope"; throws maquette::Error

// t in [0, 1] (clamped) to RGB.
std::array<uint8_t, 3> ramp_colour(Ramp ramp, double t);

}  // namespace maquette
