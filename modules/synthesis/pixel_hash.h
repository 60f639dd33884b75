// Deterministic hashes of global pixel coordinates: the jitter and the random candidates of the
// synthesis are functions of (pixel, level, pass, seed) only, never of a tile or a thread. Where
// the plane's columns repeat (the equatorial faces' row around the globe), the column is hashed
// modulo the period (wrapped_col), so that one place has one hash however it is reached.
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

// `col` modulo `period`, in [0, period); `col` itself when period is 0 (no repetition).
constexpr int64_t wrapped_col(int64_t col, int64_t period) {
  return period > 0 ? (col % period + period) % period : col;
}

}  // namespace maquette::synthesis
