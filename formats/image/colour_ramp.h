// Colour ramps for quicklooks: values to 8-bit RGB.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

namespace maquette {

// Grey, Viridis, Diverging, Terrain and Slope are stretched between two values (t in [0, 1]);
// Hypsometric maps heights in metres to fixed atlas tints: blues below sea level (0 m included:
// sea and water), greens, yellows and browns up to 4000 m, grey and white above. Viridis
// (sequential) and Diverging (blue, near-white at t = 0.5, red) are perceptually ordered and
// read by colour-blind eyes too.
enum class Ramp { Grey, Viridis, Diverging, Terrain, Slope, Hypsometric };
// "grey", "viridis", "diverging", "terrain", "slope", "hypsometric"; throws maquette::Error.
Ramp parse_ramp(std::string_view name);

// t in [0, 1] (clamped) to RGB; for Hypsometric t is in metres.
std::array<uint8_t, 3> ramp_colour(Ramp ramp, double t);

}  // namespace maquette
