// FreshArray's storage (formats/render/fresh_array.h): a big block freed is given to the next
// FreshArray it can hold (at least half its size), not to a larger or a much smaller one; small
// blocks are not kept.
#include "render/fresh_array.h"

#include <gtest/gtest.h>

#include <cstdint>

namespace maquette {
namespace {

// A size no other test's arrays have, so that the block kept is this test's.
constexpr size_t kElements = (kKeptBlockBytes / sizeof(double)) * 3 + 12345;

TEST(FreshArray, BigBlocksFreedAreReused) {
  const double* freed = nullptr;
  {
    FreshArray<double> a(kElements);
    freed = a.data();
  }
  FreshArray<double> larger(kElements + 1);  // does not fit: a new block
  EXPECT_NE(larger.data(), freed);
  FreshArray<uint8_t> small(kElements * sizeof(double) / 4);  // a quarter: a new block
  EXPECT_NE(static_cast<const void*>(small.data()), static_cast<const void*>(freed));
  FreshArray<float> half(kElements * 2 - 7);  // just under the block's bytes: the freed block
  EXPECT_EQ(static_cast<const void*>(half.data()), static_cast<const void*>(freed));
}

}  // namespace
}  // namespace maquette
