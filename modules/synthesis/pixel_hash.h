// Deterministic hashes of global pixel coordinates: the jitter and the random candidates of the
// synthesis are functions of (pixel, level, pass, seed) only, never of a tile or a thread.
#pragma once

#include <cstdint>

#include "core/splitmix64.h"

namespace maquette::synthesis {

// A hash of pixel (col, row) at `level` for the purpose `salt` (jitter, candidate j of a pass).
constexpr uint64_t pixel_hash(int64_t col, int64_t row, int level, uint64_t seed, uint64_t salt) {
  uint64_t h = splitmix64_mix(seed ^ kSplitMix64Gamma);
  h = splitmix64_mix(h ^ uint64_t(col));
  h = splitmix64_mix(h ^ uint64_t(row));
  return splitmix64_mix(h ^ (uint64_t(level) << 32) ^ salt);
}

}  // namespace maquette::synthesis
