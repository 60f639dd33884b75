#include "image/stretch.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
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
  // gathered and the ranks selected among them (equal keys, equal values). Both passes in chunks
  // side by side (a panorama's three bands shared evenly by two threads): the counts are exact
  // whatever the order they are added in, the gathered values put in the chunks' order.
  constexpr size_t kBins = size_t(1) << (32 - kShift), kChunk = size_t(1) << 16;
  const size_t chunks = (v.size() + kChunk - 1) / kChunk;
  auto chunk = [&](size_t c) {
    return v.subspan(c * kChunk, std::min(kChunk, v.size() - c * kChunk));
  };
  tbb::enumerable_thread_specific<std::vector<size_t>> counted(kBins, size_t(0));
  tbb::parallel_for(size_t(0), chunks, [&](size_t c) {
    std::vector<size_t>& counts = counted.local();
    for (const float x : chunk(c)) ++counts[order_key(x) >> kShift];
  });
  std::vector<size_t> bins(kBins, 0);
  for (const std::vector<size_t>& counts : counted)
    std::transform(bins.begin(), bins.end(), counts.begin(), bins.begin(), std::plus<>());
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
  using OfBins = std::array<std::vector<float>, 2>;
  std::vector<OfBins> of_chunk(chunks);
  tbb::parallel_for(size_t(0), chunks, [&](size_t c) {
    for (const float x : chunk(c))
      for (size_t j = 0; j < 2; ++j)
        if (order_key(x) >> kShift == bin[j]) of_chunk[c][j].push_back(x);
  });
  OfBins of_bin;
  for (const OfBins& gathered : of_chunk)
    for (size_t j = 0; j < 2; ++j)
      of_bin[j].insert(of_bin[j].end(), gathered[j].begin(), gathered[j].end());
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
