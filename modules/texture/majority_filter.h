// Majority (mode) filter of a class map: the minimum mapping unit of remote-sensing maps.
#pragma once

#include <vector>

namespace maquette::texture {

// The largest radius texture.classify and texture.assess filter with (their halo: a 1.2 km window
// at 35 m pixels).
constexpr int kMaxMajorityRadius = 16;

// `cls` holds (n + 2 radius)^2 classes (-1: none), row by row: an n x n tile and a ring of
// `radius` pixels around it. Returns the n x n tile where each classified pixel takes the most
// frequent class of the (2 radius + 1)^2 window around it (unclassified pixels do not vote and
// stay -1); ties keep the pixel's own class when it is among the most frequent, else the lowest
// id. One summed-area table per class present, so the cost does not grow with the radius.
// Preconditions: n >= 1, radius >= 0, cls.size() == (n + 2 radius)^2.
std::vector<int> majority_filter(const std::vector<int>& cls, int n, int radius);

}  // namespace maquette::texture
