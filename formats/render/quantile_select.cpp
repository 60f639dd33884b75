#include "render/quantile_select.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace maquette {
namespace {

// Unsigned keys in the floats' order: the sign bit flipped for positive values, every bit for
// negative ones.
uint32_t order_key(float x) {
  uint32_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  return (bits & 0x80000000u) ? ~bits : bits | 0x80000000u;
}

}  // namespace

StretchRange select_quantile_range(const std::vector<float>& values, double q0, double q1) {
  std::vector<size_t> count(size_t(1) << 16, 0);
  size_t n = 0;
  for (const float x : values)
    if (std::isfinite(x)) {
      ++count[order_key(x) >> 16];
      ++n;
    }
  if (n == 0) return {0.0, 1.0};
  // Each rank's bucket and its rank among the bucket's values.
  const std::array<size_t, 2> ranks{size_t(q0 * double(n - 1)), size_t(q1 * double(n - 1))};
  std::array<uint32_t, 2> bucket{};
  std::array<size_t, 2> inside{};
  for (size_t r = 0; r < 2; ++r) {
    size_t below = 0;
    uint32_t b = 0;
    while (below + count[b] <= ranks[r]) below += count[b++];
    bucket[r] = b;
    inside[r] = ranks[r] - below;
  }
  std::array<std::vector<float>, 2> gathered;
  for (size_t r = 0; r < 2; ++r) gathered[r].reserve(count[bucket[r]]);
  for (const float x : values) {
    if (!std::isfinite(x)) continue;
    const uint32_t b = order_key(x) >> 16;
    for (size_t r = 0; r < 2; ++r)
      if (b == bucket[r]) gathered[r].push_back(x);
  }
  std::array<double, 2> at{};
  for (size_t r = 0; r < 2; ++r) {
    auto it = gathered[r].begin() + std::ptrdiff_t(inside[r]);
    std::nth_element(gathered[r].begin(), it, gathered[r].end());
    at[r] = *it;
  }
  return {at[0], at[1] > at[0] ? at[1] : at[0] + 1.0};
}

}  // namespace maquette
