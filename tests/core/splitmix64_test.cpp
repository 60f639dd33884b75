#include "core/splitmix64.h"

#include <gtest/gtest.h>

#include <array>

namespace maquette {
namespace {

// The first outputs of Vigna's reference splitmix64.c seeded with 1477776061723855037, as
// published in rand_xoshiro's reference test (src/splitmix64.rs); recomputed with an independent
// Python implementation (arbitrary-precision integers masked to 64 bits) before being written here.
constexpr uint64_t kReferenceSeed = 1477776061723855037ULL;
constexpr std::array<uint64_t, 5> kReferenceOutputs = {
    1985237415132408290ULL, 2979275885539914483ULL, 13511426838097143398ULL, 8488337342461049707ULL,
    15141737807933549159ULL};

TEST(SplitMix64, GeneratorGivesTheReferenceSequence) {
  uint64_t state = kReferenceSeed;
  for (const uint64_t expected : kReferenceOutputs) EXPECT_EQ(splitmix64_next(state), expected);
  EXPECT_EQ(state, kReferenceSeed + kReferenceOutputs.size() * kSplitMix64Gamma);
}

TEST(SplitMix64, FinaliserIsTheGeneratorWithoutItsIncrement) {
  // next() of state s is the finaliser of s + gamma: the reference sequence's k-th output is the
  // finaliser of seed + k gamma (mod 2^64).
  for (size_t k = 0; k < kReferenceOutputs.size(); ++k)
    EXPECT_EQ(splitmix64_mix(kReferenceSeed + (k + 1) * kSplitMix64Gamma), kReferenceOutputs[k]);
}

}  // namespace
}  // namespace maquette
