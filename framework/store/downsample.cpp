#include "store/downsample.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>

#include "core/avx2_clones.h"
#include "core/samples.h"

namespace maquette {
namespace {

template <typename T>
T fill_value(const double* nodata) {
  if (nodata) return cast_sample<T>(*nodata);
  if constexpr (std::is_floating_point_v<T>) return std::numeric_limits<T>::quiet_NaN();
  return T{0};
}

// The mean of n <= 4 values, cast_sample<T>(sum / n). Integer dtypes (at most 32 bits) get the
// same result without floating point: |sum| / n rounded half away from zero is
// (2 |sum| + n) / 2n, and the mean of samples of T needs no clamping.
template <typename T>
T mean(const T* v, int n) {
  if constexpr (std::is_integral_v<T>) {
    static_assert(sizeof(T) <= 4, "the sum of four samples must fit in int64_t");
    int64_t sum = 0;
    for (int i = 0; i < n; ++i) sum += int64_t(v[i]);
    const int64_t a = sum < 0 ? -sum : sum;
    const int64_t q = n == 4 ? (a + 2) / 4 : (2 * a + n) / (2 * n);
    return T(sum < 0 ? -q : q);
  } else {
    double sum = 0;
    for (int i = 0; i < n; ++i) sum += double(v[i]);
    return cast_sample<T>(sum / n);
  }
}

// The most frequent of n <= 4 values, the smallest among equally frequent ones.
template <typename T>
T mode(const T* v, int n) {
  T best = v[0];
  int best_count = 0;
  for (int i = 0; i < n; ++i) {
    const int count = int(std::count(v, v + n, v[i]));
    if (count > best_count || (count == best_count && v[i] < best)) best = v[i], best_count = count;
  }
  return best;
}

template <typename T>
T load(const std::byte* p, size_t i) {
  T v;
  std::memcpy(&v, p + i * sizeof(T), sizeof(T));
  return v;
}

// One overview row of a one-channel float layer whose missing samples are NaN (no nodata
// value): the means mean() gives, without branches so that the loop vectorizes. Adding 0 for a
// missing sample changes no sum (a sum from +0 is never -0), and a mean of floats is within the
// float range, so cast_sample is the plain conversion.
MAQUETTE_AVX2_CLONES void mean_row_nan(const std::byte* top, const std::byte* bottom, size_t half,
                                       std::byte* out) {
  for (size_t c = 0; c < half; ++c) {
    const float a = load<float>(top, 2 * c), b = load<float>(top, 2 * c + 1),
                d = load<float>(bottom, 2 * c), e = load<float>(bottom, 2 * c + 1);
    // x == x: x is not NaN (in this form the loop vectorizes).
    const double n =
        (a == a ? 1.0 : 0.0) + (b == b ? 1.0 : 0.0) + (d == d ? 1.0 : 0.0) + (e == e ? 1.0 : 0.0);
    const double sum = 0.0 + (a == a ? double(a) : 0.0) + (b == b ? double(b) : 0.0) +
                       (d == d ? double(d) : 0.0) + (e == e ? double(e) : 0.0);
    const float value = n > 0 ? float(sum / n) : std::numeric_limits<float>::quiet_NaN();
    std::memcpy(out + c * sizeof(float), &value, sizeof(float));
  }
}

// The overview's samples from the children's bytes, read and written through memcpy (the tiles
// hold bytes): no copies of whole tiles, one allocation, one pass over each row pair.
template <typename T, bool kContinuous>
RawTile build(const std::array<const RawTile*, 4>& children, const LayerInfo& layer) {
  const int n = layer.tile_size, half = n / 2, channels = layer.channels;
  const double* nodata = layer.nodata ? &*layer.nodata : nullptr;
  const T fill = fill_value<T>(nodata);
  const size_t row = size_t(n) * size_t(channels);  // samples per row
  RawTile tile{layer.dtype, n, channels, std::vector<std::byte>(row * size_t(n) * sizeof(T))};
  for (int digit = 0; digit < 4; ++digit) {
    const std::byte* src = children[digit] ? children[digit]->bytes.data() : nullptr;
    const size_t col0 = size_t((digit & 1) * half) * size_t(channels);
    for (int r = 0; r < half; ++r) {
      std::byte* out =
          tile.bytes.data() + (size_t((digit >> 1) * half + r) * row + col0) * sizeof(T);
      const size_t top = size_t(2 * r) * row, bottom = top + row;
      if constexpr (std::is_same_v<T, float> && kContinuous)
        if (src && !nodata && channels == 1) {
          mean_row_nan(src + top * sizeof(T), src + bottom * sizeof(T), size_t(half), out);
          continue;
        }
      for (size_t c = 0, i = 0; c < size_t(half); ++c)
        for (size_t k = 0; k < size_t(channels); ++k, ++i) {
          const size_t left = 2 * c * size_t(channels) + k, right = left + size_t(channels);
          T value = fill;
          if (src) {
            const T block[4] = {load<T>(src, top + left), load<T>(src, top + right),
                                load<T>(src, bottom + left), load<T>(src, bottom + right)};
            T valid[4];
            int count = 0;
            for (const T v : block)
              if (!is_missing(v, nodata)) valid[count++] = v;
            if (count > 0) value = kContinuous ? mean(valid, count) : mode(valid, count);
          }
          std::memcpy(out + i * sizeof(T), &value, sizeof(T));
        }
    }
  }
  return tile;
}

}  // namespace

RawTile build_overview(const std::array<const RawTile*, 4>& children, const LayerInfo& layer) {
  return visit_dtype(layer.dtype, [&]<typename T>(std::type_identity<T>) {
    return layer.semantics == Semantics::Continuous ? build<T, true>(children, layer)
                                                    : build<T, false>(children, layer);
  });
}

}  // namespace maquette
