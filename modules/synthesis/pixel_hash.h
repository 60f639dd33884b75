// Deterministic hashes of global pixel coordinates: the jitter and the random candidates of the
// synthesis are functions of (pixel, level, pass, seed) only, never of a tile or a thread.
#pragma once

#include <cstdint>

namespace maquette::synthesis {

// splitmix64's finalizer: a bijection of 64-bit words that spreads every input bit.
constexpr uint64_t mix64(uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// A hash of pixel (col, row) at `level` for the purpose `salt` (jitter, candidate j of a pass).
constexpr uint64_t pixel_hash(int64_t col, int64_t row, int level, uint64_t seed, uint64_t salt) {
  uint64_t h = mix64(seed ^ 0x9e3779b97f4a7c15ULL);
  h = mix64(h ^ uint64_t(col));
  h = mix64(h ^ uint64_t(row));
  return mix64(h ^ (uint64_t(level) << 32) ^ salt);
}

}  // namespace maquette::synthesis
