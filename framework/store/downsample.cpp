#include "store/downsample.h"

#include <algorithm>
#include <cstdint>
#include <cstring>

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
RawTile build(const std::array<const RawTile*, 4>& children, const LayerInfo& layer) {
  const int n = layer.tile_size, half = n / 2, channels = layer.channels;
  const double* nodata = layer.nodata ? &*layer.nodata : nullptr;
  std::vector<T> out(size_t(n) * size_t(n) * size_t(channels), fill_value<T>(nodata));
  std::vector<T> src(out.size());
  for (int digit = 0; digit < 4; ++digit) {
    if (!children[digit]) continue;
    std::memcpy(src.data(), children[digit]->bytes.data(), src.size() * sizeof(T));
    const int col0 = (digit & 1) * half, row0 = (digit >> 1) * half;
    for (int r = 0; r < half; ++r)
      for (int c = 0; c < half; ++c)
        for (int k = 0; k < channels; ++k) {
          T valid[4];
          int count = 0;
          for (int dr = 0; dr < 2; ++dr)
            for (int dc = 0; dc < 2; ++dc) {
              const T v = src[(size_t(2 * r + dr) * n + size_t(2 * c + dc)) * channels + k];
              if (!is_missing(v, nodata)) valid[count++] = v;
            }
          if (count == 0) continue;  // keeps the fill value
          out[(size_t(row0 + r) * n + size_t(col0 + c)) * channels + k] =
              layer.semantics == Semantics::Continuous ? mean(valid, count) : mode(valid, count);
        }
  }
  RawTile tile{layer.dtype, n, channels, std::vector<std::byte>(out.size() * sizeof(T))};
  std::memcpy(tile.bytes.data(), out.data(), tile.bytes.size());
  return tile;
}

}  // namespace

RawTile build_overview(const std::array<const RawTile*, 4>& children, const LayerInfo& layer) {
  return visit_dtype(layer.dtype,
                     [&]<typename T>(std::type_identity<T>) { return build<T>(children, layer); });
}

}  // namespace maquette
