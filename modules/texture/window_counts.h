// Counts of marked pixels in square windows, by a summed-area table (the cost does not grow with
// the window): the majority filter's votes and the land-cover share.
#pragma once

#include <cstdint>
#include <vector>

namespace maquette::texture {

// `marked` holds (n + 2 radius)^2 flags, row by row: an n x n tile and a ring of `radius` pixels
// around it. Returns, for each pixel of the n x n tile, how many of the (2 radius + 1)^2 pixels
// of the window centred on it are marked (non-zero).
// Preconditions: n >= 1, radius >= 0, marked.size() == (n + 2 radius)^2.
std::vector<uint32_t> window_counts(const std::vector<uint8_t>& marked, int n, int radius);

}  // namespace maquette::texture
