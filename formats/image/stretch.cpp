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
constexpr size_t kChunk = size_t(1) << 16;  // values of a span counted by one task
constexpr uint32_t kFiniteBins[2] = {order_key(-std::numeric_limits<float>::max()) >> kShift,
                                     order_key(std::numeric_limits<float>::max()) >> kShift};

}  // namespace

StretchRange quantile_range(std::span<const float> v, double q0, double q1) {
  return quantile_ranges(v, 1, q0, q1)[0];
}

std::vector<StretchRange> quantile_ranges(std::span<const float> v, size_t bands, double q0,
                                          double q1) {
  const size_t chunk = kChunk / bands * bands;
  return quantile_ranges((v.size() + chunk - 1) / chunk, bands,
                         [v, chunk](size_t c, std::vector<float>&) {
                           return v.subspan(c * chunk, std::min(chunk, v.size() - c * chunk));
                         },
                         q0, q1);
}

std::vector<StretchRange> quantile_ranges(size_t chunks, size_t bands, const ValueChunk& values,
                                          double q0, double q1) {
  // The values of ranks q * (count - 1) among each band's finite ones, found without sorting them
  // all: every value counted in its band's bin, then the finite ones of the bins holding the two
  // ranks gathered and the ranks selected among them (equal keys, equal values). Both passes in
  // chunks side by side, every band at once (values read in place are read once a pass): the
  // counts are exact whatever the order they are added in, the gathered values put in the
  // chunks' order.
  constexpr size_t kBins = size_t(1) << (32 - kShift);
  tbb::enumerable_thread_specific<std::vector<float>> buffers;
  auto chunk = [&](size_t c) {
    std::vector<float>& buffer = buffers.local();
    buffer.clear();
    return values(c, buffer);
  };
  tbb::enumerable_thread_specific<std::vector<size_t>> counted(bands * kBins, size_t(0));
  tbb::parallel_for(size_t(0), chunks, [&](size_t c) {
    std::vector<size_t>& counts = counted.local();
    const std::span<const float> v = chunk(c);
    for (size_t i = 0; i < v.size(); i += bands)
      for (size_t k = 0; k < bands; ++k) ++counts[k * kBins + (order_key(v[i + k]) >> kShift)];
  });
  std::vector<size_t> bins(bands * kBins, 0);
  for (const std::vector<size_t>& counts : counted)
    std::transform(bins.begin(), bins.end(), counts.begin(), bins.begin(), std::plus<>());
  // Per band: the bins holding the two ranks and the ranks within them; no value: none.
  using Pair = std::array<size_t, 2>;
  std::vector<Pair> bin(bands), within(bands);
  std::vector<uint8_t> none(bands);
  for (size_t k = 0; k < bands; ++k) {
    const auto of_band = bins.begin() + std::ptrdiff_t(k * kBins);
    const size_t count =
        std::reduce(of_band + kFiniteBins[0], of_band + kFiniteBins[1] + 1, size_t(0));
    none[k] = count == 0;
    if (none[k]) continue;
    const Pair rank = {size_t(q0 * double(count - 1)), size_t(q1 * double(count - 1))};
    for (size_t j = 0; j < 2; ++j) {
      size_t below = 0;
      bin[k][j] = kFiniteBins[0];
      while (below + of_band[std::ptrdiff_t(bin[k][j])] <= rank[j])
        below += of_band[std::ptrdiff_t(bin[k][j]++)];
      within[k][j] = rank[j] - below;
    }
  }
  using OfBins = std::vector<std::array<std::vector<float>, 2>>;  // per band
  std::vector<OfBins> of_chunk(chunks, OfBins(bands));
  tbb::parallel_for(size_t(0), chunks, [&](size_t c) {
    const std::span<const float> v = chunk(c);
    for (size_t k = 0; k < bands; ++k) {  // a band at a time: each key made once
      if (none[k]) continue;
      const size_t low = bin[k][0], high = bin[k][1];
      auto& [of_low, of_high] = of_chunk[c][k];
      for (size_t i = k; i < v.size(); i += bands) {
        const size_t key = order_key(v[i]) >> kShift;
        if (key == low) of_low.push_back(v[i]);
        if (key == high) of_high.push_back(v[i]);
      }
    }
  });
  std::vector<StretchRange> ranges(bands, StretchRange{0.0, 1.0});
  for (size_t k = 0; k < bands; ++k) {
    if (none[k]) continue;
    auto select = [&](size_t j) {
      std::vector<float> values;
      for (const OfBins& gathered : of_chunk)
        values.insert(values.end(), gathered[k][j].begin(), gathered[k][j].end());
      const auto it = values.begin() + std::ptrdiff_t(within[k][j]);
      std::nth_element(values.begin(), it, values.end());
      return double(*it);
    };
    const double lo = select(0), hi = select(1);
    ranges[k] = {lo, hi > lo ? hi : lo + 1.0};
  }
  return ranges;
}

}  // namespace maquette
