// SplitMix64 (Steele, Lea and Flood, "Fast splittable pseudorandom number generators", OOPSLA
// 2014), with the constants of Vigna's reference splitmix64.c (prng.di.unimi.it): the golden-ratio
// increment and the finaliser's shifts and multipliers, a variant of MurmurHash3's fmix64.
//
// What it is for: deterministic pseudo-random bits that depend on their inputs alone, never on
// threads, tiling or order: the finaliser as a stateless 64-bit integer hash (instance thinning,
// lattice hashes of procedural noise), and the generator to derive a few seeds from one. Not for
// cryptography.
#pragma once

#include <cstdint>

namespace maquette {

// 2^64 / golden ratio, odd: the generator's increment (Weyl sequence).
inline constexpr uint64_t kSplitMix64Gamma = 0x9e3779b97f4a7c15ULL;

// SplitMix64's finaliser: a bijection of 64-bit integers whose every output bit depends on every
// input bit.
constexpr uint64_t splitmix64_mix(uint64_t x) {
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// The generator: advances `state` by kSplitMix64Gamma and returns the finaliser of the new state
// (splitmix64.c's next()).
constexpr uint64_t splitmix64_next(uint64_t& state) {
  state += kSplitMix64Gamma;
  return splitmix64_mix(state);
}

// A double uniform in [0, 1) from the top 53 bits of `bits` (e.g. splitmix64_next's output).
constexpr double unit_interval(uint64_t bits) { return double(bits >> 11) * 0x1.0p-53; }

}  // namespace maquette
