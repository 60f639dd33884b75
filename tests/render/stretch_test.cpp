// quantile_range (image/stretch.h) against std::nth_element over the finite values, the ranks
// q * (count - 1): values spread widely, clustered in one narrow range (many in one of its bins),
// negative with both zeros, repeated, with NaN and infinities among them, and few or none; and
// quantile_ranges of three such bands interleaved, whole and handed over in chunks of uneven sizes
// (some empty), some copied into the buffer.
#include "image/stretch.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <span>
#include <vector>

namespace maquette {
namespace {

StretchRange nth_element_range(std::vector<float> v, double q0, double q1) {
  std::erase_if(v, [](float x) { return !std::isfinite(x); });
  if (v.empty()) return {0.0, 1.0};
  auto nth = [&](double q) {
    const auto it = v.begin() + std::ptrdiff_t(q * double(v.size() - 1));
    std::nth_element(v.begin(), it, v.end());
    return double(*it);
  };
  const double lo = nth(q0), hi = nth(q1);
  return {lo, hi > lo ? hi : lo + 1.0};
}

// quantile_ranges of the bands `v` (of one size) interleaved, handed over in chunks of 0, 1, 2, ...
// 9 pixels (a value of each band), then 0 again, and so on; the odd chunks copied into the buffer,
// the even ones read in place.
std::vector<StretchRange> in_chunks(const std::vector<std::vector<float>>& v, double q0,
                                    double q1) {
  const size_t bands = v.size(), pixels = v[0].size();
  std::vector<float> interleaved;
  for (size_t i = 0; i < pixels; ++i)
    for (size_t k = 0; k < bands; ++k) interleaved.push_back(v[k][i]);
  std::vector<size_t> first = {0};  // pixels
  while (first.back() < pixels) first.push_back(std::min(pixels, first.back() + first.size() % 10));
  return quantile_ranges(
      first.size() - 1, bands,
      [&](size_t c, std::vector<float>& buffer) {
        const std::span<const float> values(interleaved.data() + bands * first[c],
                                            bands * (first[c + 1] - first[c]));
        if (c % 2 == 0) return values;
        buffer.assign(values.begin(), values.end());
        return std::span<const float>(buffer);
      },
      q0, q1);
}

TEST(Stretch, QuantilesAreTheNthElementsOfTheFiniteValues) {
  std::mt19937 random(27);
  std::uniform_real_distribution<float> unit(0, 1);
  const float inf = std::numeric_limits<float>::infinity();
  // Kinds of values: a pixel's texel, one narrow range, signed with zeros, a few repeated, any
  // magnitude.
  const std::vector<std::function<float()>> kinds = {
      [&] { return 255 * unit(random); },
      [&] { return 100 + unit(random) / 64; },
      [&] {
        return unit(random) < 0.2f ? (unit(random) < 0.5f ? -0.0f : 0.0f) : unit(random) - 0.5f;
      },
      [&] { return float(int(unit(random) * 4)); },
      [&] { return std::ldexp(unit(random) - 0.5f, int(unit(random) * 200) - 100); },
  };
  const float odd[] = {NAN, inf, -inf};
  for (const size_t size :
       {size_t(0), size_t(1), size_t(2), size_t(7), size_t(1000), size_t(200000)})
    for (size_t kind = 0; kind < kinds.size(); ++kind) {
      std::vector<float> v(size);
      for (float& x : v) x = unit(random) < 0.05f ? odd[int(unit(random) * 3) % 3] : kinds[kind]();
      for (const auto& [q0, q1] :
           {std::pair{0.02, 0.98}, std::pair{0.0, 1.0}, std::pair{0.5, 0.5}}) {
        const StretchRange want = nth_element_range(v, q0, q1), got = quantile_range(v, q0, q1);
        EXPECT_EQ(got.first, want.first) << size << " values of kind " << kind << ", q " << q0;
        EXPECT_EQ(got.second, want.second) << size << " values of kind " << kind << ", q " << q1;
      }
    }
  // Three bands, each of its own kind, interleaved: each band's quantiles its own, whether handed
  // over whole or in chunks.
  for (const size_t size : {size_t(0), size_t(1), size_t(5), size_t(1000), size_t(100000)})
    for (size_t kind = 0; kind < kinds.size(); ++kind) {
      std::vector<std::vector<float>> bands(3, std::vector<float>(size));
      for (size_t k = 0; k < 3; ++k)
        for (float& x : bands[k])
          x = unit(random) < 0.05f ? odd[int(unit(random) * 3) % 3]
                                   : kinds[(kind + k) % kinds.size()]();
      std::vector<float> interleaved;
      for (size_t i = 0; i < size; ++i)
        for (size_t k = 0; k < 3; ++k) interleaved.push_back(bands[k][i]);
      const auto whole = quantile_ranges(interleaved, 3, 0.02, 0.98);
      const auto chunked = in_chunks(bands, 0.02, 0.98);
      ASSERT_EQ(whole.size(), 3u);
      ASSERT_EQ(chunked.size(), 3u);
      for (size_t k = 0; k < 3; ++k) {
        const StretchRange want = nth_element_range(bands[k], 0.02, 0.98);
        EXPECT_EQ(whole[k], want) << size << " pixels, band " << k << " of kind " << kind;
        EXPECT_EQ(chunked[k], want)
            << size << " pixels in chunks, band " << k << " of kind " << kind;
      }
    }
  // Only NaN and infinities: none finite.
  EXPECT_EQ(quantile_range(std::vector<float>{NAN, inf, -inf}, 0.02, 0.98), StretchRange(0.0, 1.0));
}

}  // namespace
}  // namespace maquette
