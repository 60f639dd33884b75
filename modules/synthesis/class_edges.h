// The exemplar's own edges between classes: for each ordered pair of labels (a, b), the places of
// label a with label b nearby. The finest level's patch passes draw from them where a pixel's
// window holds another target class (patch_pass.h, `edges`): a place where the painting itself
// goes from one class to the other, whose patch can fit the output across the land cover's edge,
// which the copies from either side and the draws around a pixel's source rarely find.
//
// Each place is one 64-bit entry, a << 40 | b << 32 | pixel (the level's index y * width + x,
// below 2^31): the entries ascending, each pair's places are one run, in pixel order.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "exemplar_pyramid.h"

namespace maquette::synthesis {

inline constexpr int kClassEdgeReach = 8;  // pixels of the level (Chebyshev)

constexpr uint64_t class_edge_entry(uint8_t a, uint8_t b, int32_t pixel) {
  return uint64_t(a) << 40 | uint64_t(b) << 32 | uint32_t(pixel);
}
constexpr int32_t class_edge_pixel(uint64_t entry) { return int32_t(entry & 0xffffffffu); }

// The allowed pixels of `level` of each label a that have an allowed pixel of another label b
// within kClassEdgeReach, as entries (above), ascending. Labels kUnknownLabel are neither.
std::vector<uint64_t> class_edge_places(const ExemplarLevel& level);

// The run of `places` (class_edge_places's) of label a beside label b; empty when there is none.
std::span<const uint64_t> class_edge_run(const std::vector<uint64_t>& places, uint8_t a, uint8_t b);

}  // namespace maquette::synthesis
