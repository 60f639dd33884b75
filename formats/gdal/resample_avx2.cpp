// The four-samples-at-a-time kernels of resample_kernels.h (AVX2). Each does the same operations
// in the same order and precision as the one-sample kernel it stands for (no fused
// multiply-add: the target is "avx2" alone), so the same bits; lanes outside its common case go
// to that kernel.
#include <immintrin.h>

#include <cmath>

#include "gdal/resample_kernels.h"

namespace maquette::resample_detail {
namespace {

// Two neighbouring pixels, at[index] and at[index + 1], for 4 samples: lanes 0-3 of the result
// hold the first pixels, lanes 4-7 the second. (Four 64-bit loads: faster than a gather here.)
__attribute__((target("avx2"))) inline __m256 pixel_pairs(const float* at, const int* index) {
  const auto pair = [at](int k) {
    return _mm_loadl_epi64(reinterpret_cast<const __m128i*>(at + k));
  };
  const __m128i p01 = _mm_unpacklo_epi64(pair(index[0]), pair(index[1]));
  const __m128i p23 = _mm_unpacklo_epi64(pair(index[2]), pair(index[3]));
  return _mm256_permutevar8x32_ps(_mm256_castsi256_ps(_mm256_set_m128i(p23, p01)),
                                  _mm256_setr_epi32(0, 2, 4, 6, 1, 3, 5, 7));
}

// Four samples' window coordinates x = (source x - x0) / step (y alike), u = x - shift (v
// alike), the floors of u and v and those as integers; `valid`: the samples with an x (bit l,
// or lane l all ones, for sample l).
struct Taps4 {
  __m256d x, y, u, v, fcol, frow;
  __m128i col, row;
  int valid;
  __m128 valid_lanes;
};

__attribute__((target("avx2"))) inline Taps4 taps4(const Window& w, const double* x,
                                                   const double* y, double shift) {
  Taps4 t;
  const __m256d px = _mm256_loadu_pd(x), py = _mm256_loadu_pd(y);
  const __m256d valid = _mm256_cmp_pd(px, px, _CMP_ORD_Q);
  t.valid = _mm256_movemask_pd(valid);
  t.valid_lanes = _mm256_castps256_ps128(
      _mm256_permutevar8x32_ps(_mm256_castpd_ps(valid), _mm256_setr_epi32(0, 2, 4, 6, 1, 3, 5, 7)));
  __m256d u = _mm256_sub_pd(px, _mm256_set1_pd(double(w.x0)));
  __m256d v = _mm256_sub_pd(py, _mm256_set1_pd(double(w.y0)));
  if (w.step != 1) {
    const __m256d step = _mm256_set1_pd(double(w.step));
    u = _mm256_div_pd(u, step);
    v = _mm256_div_pd(v, step);
  }
  t.x = u;
  t.y = v;
  t.u = _mm256_sub_pd(u, _mm256_set1_pd(shift));
  t.v = _mm256_sub_pd(v, _mm256_set1_pd(shift));
  t.fcol = _mm256_floor_pd(t.u);
  t.frow = _mm256_floor_pd(t.v);
  t.col = _mm256_cvttpd_epi32(t.fcol);
  t.row = _mm256_cvttpd_epi32(t.frow);
  return t;
}

// Whether 0 <= col < cols and 0 <= row < rows, per lane.
__attribute__((target("avx2"))) inline __m128i in_range(__m128i col, __m128i row, int cols,
                                                        int rows) {
  const __m128i none = _mm_set1_epi32(-1);
  return _mm_and_si128(
      _mm_and_si128(_mm_cmpgt_epi32(col, none), _mm_cmpgt_epi32(_mm_set1_epi32(cols), col)),
      _mm_and_si128(_mm_cmpgt_epi32(row, none), _mm_cmpgt_epi32(_mm_set1_epi32(rows), row)));
}

// The samples of 4 lanes (bit l of `lanes` set: sample l) still NaN in o (band b of a sample
// at o[l * bands]) get values[l] where `good` has the lane, else one(l): the one-sample kernel.
template <typename One>
void put_lanes(float* o, size_t bands, const float* values, int lanes, int good, One one) {
  for (int l = 0; l < 4; ++l) {
    float& ol = o[size_t(l) * bands];
    if ((lanes >> l & 1) && std::isnan(ol)) ol = (good >> l & 1) ? values[l] : one(l);
  }
}

// put_lanes' common case in one store: one band, and every sample to fill `good` (a subset of
// `lanes`, per lane); returns whether it was.
__attribute__((target("avx2"))) inline bool put_stored(float* o, size_t bands, __m128 value,
                                                       int lanes, __m128 good) {
  if (bands != 1) return false;
  const __m128 old = _mm_loadu_ps(o), empty = _mm_cmpunord_ps(old, old);
  if ((lanes & _mm_movemask_ps(empty) & ~_mm_movemask_ps(good)) != 0) return false;
  _mm_storeu_ps(o, _mm_blendv_ps(old, value, _mm_and_ps(empty, good)));
  return true;
}

// put_lanes with `bilinear_at` for the lanes not `good`.
__attribute__((target("avx2"), noinline)) void bilinear_lanes(const Window& w, int band, __m256d u,
                                                              __m256d v, __m128 values, int lanes,
                                                              int good, float* o) {
  alignas(32) double us[4], vs[4];
  alignas(16) float vals[4];
  _mm256_store_pd(us, u);
  _mm256_store_pd(vs, v);
  _mm_store_ps(vals, values);
  put_lanes(o, w.planes.size(), vals, lanes, good, [&](int l) {
    const int col = ifloor(us[l]), row = ifloor(vs[l]);
    return bilinear_at(w, band, col, row, us[l] - col, vs[l] - row);
  });
}

// `keys`' two pieces of four distances (the same operations, a = -0.5).
__attribute__((target("avx2"))) inline __m256d keys_near4(__m256d d) {
  return _mm256_add_pd(
      _mm256_mul_pd(
          _mm256_mul_pd(_mm256_sub_pd(_mm256_mul_pd(_mm256_set1_pd(1.5), d), _mm256_set1_pd(2.5)),
                        d),
          d),
      _mm256_set1_pd(1));
}

__attribute__((target("avx2"))) inline __m256d keys_far4(__m256d d) {
  return _mm256_sub_pd(
      _mm256_mul_pd(
          _mm256_add_pd(
              _mm256_mul_pd(
                  _mm256_sub_pd(_mm256_mul_pd(_mm256_set1_pd(-0.5), d), _mm256_set1_pd(-2.5)), d),
              _mm256_set1_pd(-4)),
          d),
      _mm256_set1_pd(-2));
}

// `keys` of four offsets.
__attribute__((target("avx2"))) inline void keys4(__m256d t, __m256d out[4]) {
  out[0] = keys_far4(_mm256_add_pd(_mm256_set1_pd(1), t));
  out[1] = keys_near4(t);
  out[2] = keys_near4(_mm256_sub_pd(_mm256_set1_pd(1), t));
  out[3] = keys_far4(_mm256_sub_pd(_mm256_set1_pd(2), t));
}

}  // namespace

// `w.at` of the pixel holding each point, four samples at a time, for samples [0, n) (n a
// multiple of 4): the same floors, the same pixel, NaN outside the window.
__attribute__((target("avx2"))) void nearest4(const Window& w, const WindowPoints& p, size_t n,
                                              std::span<float> out) {
  const size_t bands = w.planes.size();
  const __m128i width = _mm_set1_epi32(w.w);
  for (size_t i = 0; i < n; i += 4) {
    const Taps4 t = taps4(w, p.x.data() + i, p.y.data() + i, 0);
    if (!t.valid) continue;
    const __m128i inside = in_range(t.col, t.row, w.w, w.h);
    const __m128i index = _mm_add_epi32(_mm_mullo_epi32(t.row, width), t.col);
    for (size_t b = 0; b < bands; ++b) {
      const __m128 value = _mm_mask_i32gather_ps(_mm_set1_ps(kNaN), w.planes[b].data(), index,
                                                 _mm_castsi128_ps(inside), 4);
      float* o = out.data() + i * bands + b;
      if (put_stored(o, bands, value, t.valid, t.valid_lanes)) continue;
      alignas(16) float values[4];
      _mm_store_ps(values, value);
      put_lanes(o, bands, values, t.valid, t.valid, [](int) { return kNaN; });
    }
  }
}

// `bilinear_at` four samples at a time, for samples [0, n) (n a multiple of 4): the same
// operations in the same order and precision (floor, the float sum as the NaN test, the blend
// in double without fused multiply-adds), so the same bits. Lanes outside its common case (a
// pixel outside the window or missing) go to `bilinear_at`.
__attribute__((target("avx2"))) void bilinear4(const Window& w, const WindowPoints& p, size_t n,
                                               std::span<float> out) {
  const size_t bands = w.planes.size();
  const __m256d one = _mm256_set1_pd(1.0);
  const __m128i width = _mm_set1_epi32(w.w);
  for (size_t i = 0; i < n; i += 4) {
    const Taps4 t = taps4(w, p.x.data() + i, p.y.data() + i, 0.5);
    const int valid = t.valid;
    if (!valid) continue;
    const __m256d u = t.u, v = t.v;
    const __m256d fu = _mm256_sub_pd(u, t.fcol), fv = _mm256_sub_pd(v, t.frow);
    const __m128i col = t.col, row = t.row;
    const __m128i inside = in_range(col, row, w.w - 1, w.h - 1);
    if (_mm_testz_si128(inside, inside)) {  // no lane in the common case
      for (size_t b = 0; b < bands; ++b)
        bilinear_lanes(w, int(b), u, v, _mm_setzero_ps(), valid, 0, out.data() + i * bands + b);
      continue;
    }
    // Lanes outside it read the window's first pixels (there are two rows of two when a lane is
    // inside), and are recomputed by `bilinear_at`.
    alignas(16) int index[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(index),
                    _mm_and_si128(inside, _mm_add_epi32(_mm_mullo_epi32(row, width), col)));
    const __m256d gu = _mm256_sub_pd(one, fu), gv = _mm256_sub_pd(one, fv);
    for (size_t b = 0; b < bands; ++b) {
      const float* plane = w.planes[b].data();
      const __m256 ab = pixel_pairs(plane, index), cd = pixel_pairs(plane + w.w, index);
      const __m128 a = _mm256_castps256_ps128(ab), bb = _mm256_extractf128_ps(ab, 1);
      const __m128 c = _mm256_castps256_ps128(cd), d = _mm256_extractf128_ps(cd, 1);
      const __m128 sum = _mm_add_ps(_mm_add_ps(_mm_add_ps(a, bb), c), d);
      const __m128 in = _mm_castsi128_ps(inside), gaps = _mm_and_ps(_mm_cmpunord_ps(sum, sum), in);
      __m128 good = _mm_andnot_ps(gaps, in);
      const __m256d top = _mm256_add_pd(_mm256_mul_pd(gu, _mm256_cvtps_pd(a)),
                                        _mm256_mul_pd(fu, _mm256_cvtps_pd(bb)));
      const __m256d bottom = _mm256_add_pd(_mm256_mul_pd(gu, _mm256_cvtps_pd(c)),
                                           _mm256_mul_pd(fu, _mm256_cvtps_pd(d)));
      __m128 value =
          _mm256_cvtpd_ps(_mm256_add_pd(_mm256_mul_pd(gv, top), _mm256_mul_pd(fv, bottom)));
      if (_mm_movemask_ps(gaps)) {
        // All four pixels missing (outside a scene's edge, a void): NaN, as `bilinear_at` gives.
        const __m128 none_valid =
            _mm_and_ps(_mm_and_ps(_mm_cmpunord_ps(a, a), _mm_cmpunord_ps(bb, bb)),
                       _mm_and_ps(_mm_cmpunord_ps(c, c), _mm_cmpunord_ps(d, d)));
        good = _mm_or_ps(good, _mm_and_ps(none_valid, in));
        value = _mm_blendv_ps(value, _mm_set1_ps(kNaN), none_valid);
      }
      float* o = out.data() + i * bands + b;
      if (!put_stored(o, bands, value, valid, good))
        bilinear_lanes(w, int(b), u, v, value, valid, _mm_movemask_ps(good), o);
    }
  }
}

// `cubic` four samples at a time, for samples [0, n) (n a multiple of 4): Keys' weights and the
// sums in the same order and precision, so the same bits. Lanes with a pixel of the 4 x 4
// outside the window or missing go to `cubic` (which takes bilinear there).
__attribute__((target("avx2"))) void cubic4(const Window& w, const WindowPoints& p, size_t n,
                                            std::span<float> out) {
  const size_t bands = w.planes.size();
  const __m128i one = _mm_set1_epi32(1), width = _mm_set1_epi32(w.w);
  for (size_t i = 0; i < n; i += 4) {
    const Taps4 t = taps4(w, p.x.data() + i, p.y.data() + i, 0.5);
    if (!t.valid) continue;
    const __m128i col = _mm_sub_epi32(t.col, one), row = _mm_sub_epi32(t.row, one);
    const __m128i inside = in_range(col, row, w.w - 3, w.h - 3);
    alignas(32) double xs[4], ys[4];
    _mm256_store_pd(xs, t.x);
    _mm256_store_pd(ys, t.y);
    alignas(16) float values[4] = {};
    const auto one_by_one = [&](int b, int good) {
      put_lanes(out.data() + i * bands + size_t(b), bands, values, t.valid, good,
                [&](int l) { return cubic(w, b, xs[l], ys[l]); });
    };
    if (_mm_testz_si128(inside, inside)) {  // no lane with its 4 x 4 in the window
      for (size_t b = 0; b < bands; ++b) one_by_one(int(b), 0);
      continue;
    }
    // Lanes outside read the window's first 4 x 4 (there is one when a lane is inside).
    alignas(16) int index[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(index),
                    _mm_and_si128(inside, _mm_add_epi32(_mm_mullo_epi32(row, width), col)));
    __m256d wu[4], wv[4];
    keys4(_mm256_sub_pd(t.u, t.fcol), wu);
    keys4(_mm256_sub_pd(t.v, t.frow), wv);
    for (size_t b = 0; b < bands; ++b) {
      const float* plane = w.planes[b].data();
      __m128 gaps = _mm_setzero_ps();
      __m256d sum = _mm256_setzero_pd();
      for (int r = 0; r < 4; ++r) {
        const float* at = plane + size_t(r) * size_t(w.w);
        // Row r of each lane's 4 x 4, then s_a: pixel a of that row for the four lanes.
        __m128 s0 = _mm_loadu_ps(at + index[0]), s1 = _mm_loadu_ps(at + index[1]),
               s2 = _mm_loadu_ps(at + index[2]), s3 = _mm_loadu_ps(at + index[3]);
        _MM_TRANSPOSE4_PS(s0, s1, s2, s3);
        gaps = _mm_or_ps(gaps, _mm_or_ps(_mm_cmpunord_ps(s0, s1), _mm_cmpunord_ps(s2, s3)));
        __m256d line = _mm256_setzero_pd();
        line = _mm256_add_pd(line, _mm256_mul_pd(wu[0], _mm256_cvtps_pd(s0)));
        line = _mm256_add_pd(line, _mm256_mul_pd(wu[1], _mm256_cvtps_pd(s1)));
        line = _mm256_add_pd(line, _mm256_mul_pd(wu[2], _mm256_cvtps_pd(s2)));
        line = _mm256_add_pd(line, _mm256_mul_pd(wu[3], _mm256_cvtps_pd(s3)));
        sum = _mm256_add_pd(sum, _mm256_mul_pd(wv[r], line));
      }
      const __m128 value = _mm256_cvtpd_ps(sum);
      const __m128 good = _mm_andnot_ps(gaps, _mm_castsi128_ps(inside));
      if (put_stored(out.data() + i * bands + b, bands, value, t.valid, good)) continue;
      _mm_store_ps(values, value);
      one_by_one(int(b), _mm_movemask_ps(good));
    }
  }
}

}  // namespace maquette::resample_detail
