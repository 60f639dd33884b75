#include "image/stretch.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <vector>

namespace maquette {

namespace {

// The order of floats as unsigned integers: for a and b not NaN, a < b exactly when
// order_key(a) < order_key(b); both zeros one key.
constexpr uint32_t order_key(float x) {
  const auto bits = std::bit_cast<uint32_t>(x + 0.0f);  // -0 + 0 is +0
  return bits & 0x80000000u ? ~bits : bits | 0x80000000u;
}

// Values are counted by the top 16 bits of their keys. The infinities and NaNs have bins of their
// own, below and above those of the finite values.
constexpr int kShift = 16;
constexpr uint32_t kFiniteBins[2] = {order_key(-std::numeric_limits<float>::max()) >> kShift,
                                     order_key(std::numeric_limits<float>::max()) >> kShift};

}  // namespace

StretchRange quantile_range(std::span<const float> v, double q0, double q1) {
  // The values of ranks q * (count - 1) among the finite ones, found without sorting them all:
  // every value counted in its bin, then the finite ones of the bins holding the two ranks
  // gathered and the ranks selected among them (equal keys, equal values).
  std::vector<size_t> bins(size_t(1) << (32 - kShift), 0);
  for (const float x : v) ++bins[order_key(x) >> kShift];
  const auto first = bins.begin() + kFiniteBins[0], end = bins.begin() + kFiniteBins[1] + 1;
  const size_t count = std::reduce(first, end, size_t(0));
  if (count == 0) return {0.0, 1.0};
  const std::array<size_t, 2> rank = {size_t(q0 * double(count - 1)),
                                      size_t(q1 * double(count - 1))};
  std::array<uint32_t, 2> bin = {kFiniteBins[0], kFiniteBins[0]};
  std::array<size_t, 2> within{};  // the rank among the values of its bin
  for (size_t j = 0; j < 2; ++j) {
    size_t below = 0;
    while (below + bins[bin[j]] <= rank[j]) below += bins[bin[j]++];
    within[j] = rank[j] - below;
  }
  std::array<std::vector<float>, 2> of_bin;
  for (const float x : v)
    for (size_t j = 0; j < 2; ++j)
      if (order_key(x) >> kShift == bin[j]) of_bin[j].push_back(x);
  auto select = [&](size_t j) {
    auto& values = of_bin[j];
    const auto it = values.begin() + std::ptrdiff_t(within[j]);
    std::nth_element(values.begin(), it, values.end());
    return double(*it);
  };
  const double lo = select(0), hi = select(1);
  return {lo, hi > lo ? hi : lo + 1.0};
}

}  // namespace maquette
