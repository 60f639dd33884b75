#include "layer_kernels.h"

#include <immintrin.h>

#include <algorithm>

#include "surface.h"

namespace maquette::texture {

PairTable pair_table(const PaddedTable& t) {
  PairTable p;
  for (size_t i = 0; i <= kBins; ++i) p[2 * i] = t[i], p[2 * i + 1] = t[i + 1];
  return p;
}

namespace {

void coordinates_plain(const float* values, size_t n, float scale, float offset, float* out) {
  for (size_t c = 0; c < n; ++c) out[c] = table_coordinate(values[c] * scale + offset);
}

size_t constrain_plain(const ConstrainRow& row, const uint16_t* blocks, size_t n, uint16_t* kept) {
  size_t n_kept = 0;
  for (size_t k = 0; k < n; ++k) {
    const uint16_t block = blocks[k];
    const size_t c0 = size_t(block) * kBlock;
    std::array<float, kBlock> p;
    bool any = false;
    for (size_t i = 0; i < kBlock; ++i) {
      p[i] = row.parent[c0 + i] > 0 ? 1.0f : 0.0f;
      any |= p[i] > 0;
    }
    for (const ConstraintRow& q : row.constraints) {
      if (!any) break;  // the products stay 0
      any = false;
      for (size_t i = 0; i < kBlock; ++i) {
        const float x =
            q.coordinate
                ? q.coordinate[c0 + i]
                : table_coordinate(row.height[c0 + i] * row.height_scale + row.height_offset);
        const int j = int(x);  // lookup_at (surface.h) on the pair
        const float* b = q.pairs + 2 * j;
        p[i] = p[i] * (b[0] + (x - float(j)) * (b[1] - b[0]));
        any |= p[i] > 0;
      }
    }
    std::copy(p.begin(), p.end(), row.product + c0);
    kept[n_kept] = block;
    n_kept += any;
  }
  return n_kept;
}

void blend_plain(const BlendRow& row, const uint16_t* blocks, size_t n) {
  for (size_t k = 0; k < n; ++k) {
    const size_t c0 = size_t(blocks[k]) * kBlock;
    for (size_t c = c0; c < c0 + kBlock; ++c) {
      const float nx = row.noise ? row.noise[c] : 0.0f;
      const float cv = std::clamp((row.bias + row.noise_scale * nx) * row.product[c], 0.0f, 1.0f) *
                       row.parent[c];
      row.coverage[c] = cv;
      for (size_t i = 0; i < 3; ++i) row.rgb[i][c] = (1 - cv) * row.rgb[i][c] + cv * row.colour[i];
      row.height[c] += cv * row.roughness_m * nx;
      if (cv >= 0.5f) row.dominant[c] = row.layer;
    }
  }
}

// The same operations as above, 8 pixels at a time. Clamps as std::clamp (the bound first, so
// that -0 and NaN pass as they do there).
__attribute__((target("avx2"))) __m256 clamp8(__m256 v, __m256 lo, __m256 hi) {
  return _mm256_min_ps(hi, _mm256_max_ps(lo, v));
}

// table_coordinate of 8 values.
__attribute__((target("avx2"))) __m256 coordinate8(__m256 unit) {
  const __m256 bins = _mm256_set1_ps(float(kBins));
  return _mm256_blendv_ps(clamp8(_mm256_sub_ps(_mm256_mul_ps(unit, bins), _mm256_set1_ps(0.5f)),
                                 _mm256_setzero_ps(), _mm256_set1_ps(float(kBins - 1))),
                          bins, _mm256_cmp_ps(unit, unit, _CMP_UNORD_Q));
}

__attribute__((target("avx2"))) void coordinates_avx2(const float* values, size_t n, float scale,
                                                      float offset, float* out) {
  const __m256 s = _mm256_set1_ps(scale), o = _mm256_set1_ps(offset);
  size_t c = 0;
  for (; c + kBlock <= n; c += kBlock)
    _mm256_storeu_ps(out + c,
                     coordinate8(_mm256_add_ps(_mm256_mul_ps(_mm256_loadu_ps(values + c), s), o)));
  coordinates_plain(values + c, n - c, scale, offset, out + c);
}

__attribute__((target("avx2"))) size_t constrain_avx2(const ConstrainRow& row,
                                                      const uint16_t* blocks, size_t n,
                                                      uint16_t* kept) {
  const __m256 zero = _mm256_setzero_ps(), one = _mm256_set1_ps(1),
               scale = _mm256_set1_ps(row.height_scale), offset = _mm256_set1_ps(row.height_offset);
  size_t n_kept = 0;
  for (size_t k = 0; k < n; ++k) {
    const uint16_t block = blocks[k];
    const size_t c0 = size_t(block) * kBlock;
    __m256 p =
        _mm256_and_ps(_mm256_cmp_ps(_mm256_loadu_ps(row.parent + c0), zero, _CMP_GT_OQ), one);
    int any = _mm256_movemask_ps(_mm256_cmp_ps(p, zero, _CMP_GT_OQ));
    for (const ConstraintRow& q : row.constraints) {
      if (!any) break;
      __m256 x;
      if (q.coordinate) {
        x = _mm256_loadu_ps(q.coordinate + c0);
      } else {  // the height's
        x = coordinate8(
            _mm256_add_ps(_mm256_mul_ps(_mm256_loadu_ps(row.height + c0), scale), offset));
      }
      const __m256i i = _mm256_cvttps_epi32(x);
      // The pairs of pixels 0 to 3 and 4 to 7, then the first and second values of each. Loaded
      // one by one: faster than the gather instructions on the processors measured.
      alignas(32) int at[kBlock];
      _mm256_store_si256(reinterpret_cast<__m256i*>(at), i);
      const double* pairs = reinterpret_cast<const double*>(q.pairs);
      const auto pair = [&](int a, int b) __attribute__((target("avx2"))) {
        return _mm_loadh_pd(_mm_load_sd(pairs + at[a]), pairs + at[b]);
      };
      const __m256 low = _mm256_castpd_ps(_mm256_set_m128d(pair(2, 3), pair(0, 1))),
                   high = _mm256_castpd_ps(_mm256_set_m128d(pair(6, 7), pair(4, 5)));
      const __m256 b0 = _mm256_castpd_ps(_mm256_permute4x64_pd(
                       _mm256_castps_pd(_mm256_shuffle_ps(low, high, _MM_SHUFFLE(2, 0, 2, 0))),
                       _MM_SHUFFLE(3, 1, 2, 0))),
                   b1 = _mm256_castpd_ps(_mm256_permute4x64_pd(
                       _mm256_castps_pd(_mm256_shuffle_ps(low, high, _MM_SHUFFLE(3, 1, 3, 1))),
                       _MM_SHUFFLE(3, 1, 2, 0)));
      p = _mm256_mul_ps(p, _mm256_add_ps(b0, _mm256_mul_ps(_mm256_sub_ps(x, _mm256_cvtepi32_ps(i)),
                                                           _mm256_sub_ps(b1, b0))));
      any = _mm256_movemask_ps(_mm256_cmp_ps(p, zero, _CMP_GT_OQ));
    }
    _mm256_storeu_ps(row.product + c0, p);
    kept[n_kept] = block;
    n_kept += any != 0;
  }
  return n_kept;
}

__attribute__((target("avx2"))) void blend_avx2(const BlendRow& row, const uint16_t* blocks,
                                                size_t n) {
  const __m256 zero = _mm256_setzero_ps(), one = _mm256_set1_ps(1), bias = _mm256_set1_ps(row.bias),
               scale = _mm256_set1_ps(row.noise_scale), roughness = _mm256_set1_ps(row.roughness_m),
               half = _mm256_set1_ps(0.5f),
               layer = _mm256_castsi256_ps(_mm256_set1_epi32(row.layer));
  for (size_t k = 0; k < n; ++k) {
    const size_t c0 = size_t(blocks[k]) * kBlock;
    const __m256 nx = row.noise ? _mm256_loadu_ps(row.noise + c0) : zero;
    const __m256 cv =
        _mm256_mul_ps(clamp8(_mm256_mul_ps(_mm256_add_ps(bias, _mm256_mul_ps(scale, nx)),
                                           _mm256_loadu_ps(row.product + c0)),
                             zero, one),
                      _mm256_loadu_ps(row.parent + c0));
    _mm256_storeu_ps(row.coverage + c0, cv);
    const __m256 keep = _mm256_sub_ps(one, cv);
    for (size_t i = 0; i < 3; ++i) {
      float* rgb = row.rgb[i] + c0;
      _mm256_storeu_ps(rgb, _mm256_add_ps(_mm256_mul_ps(keep, _mm256_loadu_ps(rgb)),
                                          _mm256_mul_ps(cv, _mm256_set1_ps(row.colour[i]))));
    }
    const __m256 dh = _mm256_mul_ps(_mm256_mul_ps(cv, roughness), nx);
    float* h = row.height + c0;
    _mm256_storeu_ps(h, _mm256_add_ps(_mm256_loadu_ps(h), dh));
    __m256i* dominant = reinterpret_cast<__m256i*>(row.dominant + c0);
    _mm256_storeu_si256(dominant, _mm256_castps_si256(_mm256_blendv_ps(
                                      _mm256_castsi256_ps(_mm256_loadu_si256(dominant)), layer,
                                      _mm256_cmp_ps(cv, half, _CMP_GE_OQ))));
  }
}

}  // namespace

const LayerKernels& plain_kernels() {
  static const LayerKernels k{coordinates_plain, constrain_plain, blend_plain};
  return k;
}

const LayerKernels* avx2_kernels() {
  static const LayerKernels k{coordinates_avx2, constrain_avx2, blend_avx2};
  return __builtin_cpu_supports("avx2") ? &k : nullptr;
}

const LayerKernels& fastest_kernels() {
  static const LayerKernels& k = avx2_kernels() ? *avx2_kernels() : plain_kernels();
  return k;
}

}  // namespace maquette::texture
