#include "gradient_noise.h"

#include <immintrin.h>

#include <algorithm>
#include <bit>
#include <cmath>

// Both paths do the same IEEE operations in the same order on every point (no FMA: the AVX2 path
// is compiled for "avx2" only, and the default target has no FMA to contract into), so they give
// the same bits (gradient_noise_test.cpp).
namespace maquette::texture {
namespace {

// Hash of a lattice node: its wrapped coordinates times these odd constants, combined by xor
// with the seed, then Wellons' lowbias32 finaliser; the gradient is its top 4 bits. The
// finaliser's first xorshift distributes over the xor, so it is applied to each axis' term (6
// per point instead of 8), and its last (h ^ h >> 16) never reaches the top 16 bits: left out.
constexpr uint32_t kPrimeX = 0x8da6b343u, kPrimeY = 0xd8163841u, kPrimeZ = 0xcb1ab31fu;
constexpr uint32_t kMix1 = 0x7feb352du, kMix2 = 0x846ca68bu;
constexpr double kCellBits = 6755399441055744.0;  // 1.5 * 2^52: the ulp of x + kCellBits is 1
constexpr uint32_t kCellOffset = 0x80000000u;

uint32_t spread(uint32_t h) { return h ^ (h >> 16); }

// The rest of the finaliser, on the xor of spread() terms.
uint32_t mix(uint32_t h) {
  h *= kMix1;
  h ^= h >> 15;
  return h * kMix2;
}

// Dot product of one of the 12 cube-edge gradients (Perlin 2002; 16 cases, 4 repeated), picked
// by the top 4 bits of h, with (x, y, z).
float grad(uint32_t h, float x, float y, float z) {
  const uint32_t g = h >> 28;
  const float u = g < 8 ? x : y;
  const float v = g < 4 ? y : (g == 12 || g == 14 ? x : z);
  return ((g & 1) ? -u : u) + ((g & 2) ? -v : v);
}

float fade(float t) { return t * t * t * (t * (t * 6 - 15) + 10); }
float lerp(float a, float b, float t) { return a + t * (b - a); }

// A coordinate x in lattice units (|x| < 2^51, so any point on the globe): its cell, floor(x)
// mod 2^32 offset by 2^31, and the fraction of the way across it. floor(x) mod 2^32 is exact as
// the low 32 bits of floor(x) + kCellBits (a double in [2^52, 2^53), whose bits below its
// leading one are floor(x) + 2^51).
struct Axis {
  uint32_t cell;
  float t;
};

Axis axis(double x) {
  const double f = std::floor(x);
  return {uint32_t(std::bit_cast<uint64_t>(f + kCellBits)) ^ kCellOffset, float(x - f)};
}

// Point k of the input.
float noise_at(const GradientNoiseInput& in, int k) {
  const Coordinates& p = in.position;
  const Axis ax = axis(p[0][k] * in.scale + in.offset[0]),
             ay = axis(p[1][k] * in.scale + in.offset[1]),
             az = axis(p[2][k] * in.scale + in.offset[2]);
  const uint32_t x0 = ax.cell * kPrimeX, y0 = ay.cell * kPrimeY, z0 = az.cell * kPrimeZ;
  const uint32_t hx0 = spread(x0), hx1 = spread(x0 + kPrimeX);
  const uint32_t hy0 = spread(y0), hy1 = spread(y0 + kPrimeY);
  const uint32_t hz0 = spread(z0 ^ in.seed), hz1 = spread((z0 + kPrimeZ) ^ in.seed);
  const float X = ax.t, Y = ay.t, Z = az.t, X1 = X - 1, Y1 = Y - 1, Z1 = Z - 1;
  const float u = fade(X), v = fade(Y), w = fade(Z);
  return lerp(
      lerp(lerp(grad(mix(hx0 ^ hy0 ^ hz0), X, Y, Z), grad(mix(hx1 ^ hy0 ^ hz0), X1, Y, Z), u),
           lerp(grad(mix(hx0 ^ hy1 ^ hz0), X, Y1, Z), grad(mix(hx1 ^ hy1 ^ hz0), X1, Y1, Z), u), v),
      lerp(lerp(grad(mix(hx0 ^ hy0 ^ hz1), X, Y, Z1), grad(mix(hx1 ^ hy0 ^ hz1), X1, Y, Z1), u),
           lerp(grad(mix(hx0 ^ hy1 ^ hz1), X, Y1, Z1), grad(mix(hx1 ^ hy1 ^ hz1), X1, Y1, Z1), u),
           v),
      w);
}

// The same operations on 8 points, one per lane.
#define AVX2 __attribute__((target("avx2")))

struct Axis8 {
  __m256i cell;
  __m256 t;
};

// The cells of floor(x) f0 (points 0 .. 3) and f1 (points 4 .. 7): the low halves of the 64-bit
// lanes of f + kCellBits, gathered in point order.
AVX2 __m256i cells8(__m256d f0, __m256d f1) {
  const __m256d bits = _mm256_set1_pd(kCellBits);
  const __m256 low = _mm256_shuffle_ps(_mm256_castpd_ps(_mm256_add_pd(f0, bits)),
                                       _mm256_castpd_ps(_mm256_add_pd(f1, bits)),
                                       _MM_SHUFFLE(2, 0, 2, 0));  // f0 0 1, f1 0 1 | f0 2 3, f1 2 3
  return _mm256_xor_si256(
      _mm256_permute4x64_epi64(_mm256_castps_si256(low), _MM_SHUFFLE(3, 1, 2, 0)),
      _mm256_set1_epi32(int(kCellOffset)));
}

// Axis a of the 8 points from k on.
AVX2 Axis8 axis8(const GradientNoiseInput& in, int k, int a) {
  const __m256d scale = _mm256_set1_pd(in.scale), offset = _mm256_set1_pd(in.offset[size_t(a)]);
  const double* x = in.position[size_t(a)] + k;
  __m256d f[2];
  __m128 t[2];
  for (int half = 0; half < 2; ++half) {
    const __m256d v = _mm256_add_pd(_mm256_mul_pd(_mm256_loadu_pd(x + 4 * half), scale), offset);
    f[half] = _mm256_floor_pd(v);
    t[half] = _mm256_cvtpd_ps(_mm256_sub_pd(v, f[half]));
  }
  return {cells8(f[0], f[1]), _mm256_set_m128(t[1], t[0])};
}

AVX2 __m256i spread8(__m256i h) { return _mm256_xor_si256(h, _mm256_srli_epi32(h, 16)); }

AVX2 __m256i mix8(__m256i h) {
  h = _mm256_mullo_epi32(h, _mm256_set1_epi32(int(kMix1)));
  h = _mm256_xor_si256(h, _mm256_srli_epi32(h, 15));
  return _mm256_mullo_epi32(h, _mm256_set1_epi32(int(kMix2)));
}

// grad() with the cases as masks in the sign bit: bit 31 of h is g & 8, bit 30 g & 4, bit 29
// g & 2, bit 28 g & 1.
AVX2 __m256 grad8(__m256i h, __m256 x, __m256 y, __m256 z) {
  const __m256i sign = _mm256_set1_epi32(int(0x80000000u));
  const __m256i h1 = _mm256_slli_epi32(h, 1), h2 = _mm256_slli_epi32(h, 2),
                h3 = _mm256_slli_epi32(h, 3);
  const __m256 u = _mm256_blendv_ps(x, y, _mm256_castsi256_ps(h));               // g >= 8
  const __m256i is_12_or_14 = _mm256_andnot_si256(h3, _mm256_and_si256(h, h1));  // g & 13 == 12
  const __m256 xz = _mm256_blendv_ps(z, x, _mm256_castsi256_ps(is_12_or_14));
  const __m256 v = _mm256_blendv_ps(y, xz, _mm256_castsi256_ps(_mm256_or_si256(h, h1)));  // g >= 4
  return _mm256_add_ps(_mm256_xor_ps(u, _mm256_castsi256_ps(_mm256_and_si256(h3, sign))),
                       _mm256_xor_ps(v, _mm256_castsi256_ps(_mm256_and_si256(h2, sign))));
}

AVX2 __m256 fade8(__m256 t) {
  const __m256 t3 = _mm256_mul_ps(_mm256_mul_ps(t, t), t);
  const __m256 inner = _mm256_sub_ps(_mm256_mul_ps(t, _mm256_set1_ps(6)), _mm256_set1_ps(15));
  return _mm256_mul_ps(t3, _mm256_add_ps(_mm256_mul_ps(t, inner), _mm256_set1_ps(10)));
}

AVX2 __m256 lerp8(__m256 a, __m256 b, __m256 t) {
  return _mm256_add_ps(a, _mm256_mul_ps(t, _mm256_sub_ps(b, a)));
}

// The 8 points from k on.
AVX2 __m256 noise8(const GradientNoiseInput& in, int k) {
  const Axis8 ax = axis8(in, k, 0), ay = axis8(in, k, 1), az = axis8(in, k, 2);
  const __m256i px = _mm256_set1_epi32(int(kPrimeX)), py = _mm256_set1_epi32(int(kPrimeY)),
                pz = _mm256_set1_epi32(int(kPrimeZ)), seed = _mm256_set1_epi32(int(in.seed));
  const __m256i x0 = _mm256_mullo_epi32(ax.cell, px), y0 = _mm256_mullo_epi32(ay.cell, py),
                z0 = _mm256_mullo_epi32(az.cell, pz);
  const __m256i hx0 = spread8(x0), hx1 = spread8(_mm256_add_epi32(x0, px));
  const __m256i hy0 = spread8(y0), hy1 = spread8(_mm256_add_epi32(y0, py));
  const __m256i hz0 = spread8(_mm256_xor_si256(z0, seed)),
                hz1 = spread8(_mm256_xor_si256(_mm256_add_epi32(z0, pz), seed));
  const __m256i h00 = _mm256_xor_si256(hx0, hy0), h10 = _mm256_xor_si256(hx1, hy0),
                h01 = _mm256_xor_si256(hx0, hy1), h11 = _mm256_xor_si256(hx1, hy1);
  const __m256 one = _mm256_set1_ps(1);
  const __m256 X = ax.t, Y = ay.t, Z = az.t, X1 = _mm256_sub_ps(X, one), Y1 = _mm256_sub_ps(Y, one),
               Z1 = _mm256_sub_ps(Z, one);
  const __m256 u = fade8(X), v = fade8(Y), w = fade8(Z);
  auto g = [&](__m256i hxy, __m256i hz, __m256 x, __m256 y, __m256 z)
               AVX2 { return grad8(mix8(_mm256_xor_si256(hxy, hz)), x, y, z); };
  return lerp8(lerp8(lerp8(g(h00, hz0, X, Y, Z), g(h10, hz0, X1, Y, Z), u),
                     lerp8(g(h01, hz0, X, Y1, Z), g(h11, hz0, X1, Y1, Z), u), v),
               lerp8(lerp8(g(h00, hz1, X, Y, Z1), g(h10, hz1, X1, Y, Z1), u),
                     lerp8(g(h01, hz1, X, Y1, Z1), g(h11, hz1, X1, Y1, Z1), u), v),
               w);
}

}  // namespace

void gradient_noise_portable(const GradientNoiseInput& in, float* out) {
  for (int k = 0; k < in.n; ++k) out[k] = noise_at(in, k);
}

bool gradient_noise_has_avx2() { return __builtin_cpu_supports("avx2"); }

AVX2 void gradient_noise_avx2(const GradientNoiseInput& in, float* out) {
  int k = 0;
  for (; k + 8 <= in.n; k += 8) _mm256_storeu_ps(out + k, noise8(in, k));
  if (k == in.n) return;
  // The last points, padded with copies of the last one.
  std::array<std::array<double, 8>, 3> rest;
  for (size_t a = 0; a < 3; ++a)
    for (int m = 0; m < 8; ++m) rest[a][size_t(m)] = in.position[a][std::min(k + m, in.n - 1)];
  GradientNoiseInput padded = in;
  padded.position = {rest[0].data(), rest[1].data(), rest[2].data()};
  float value[8];
  _mm256_storeu_ps(value, noise8(padded, 0));
  std::copy(value, value + (in.n - k), out + k);
}

void gradient_noise(const GradientNoiseInput& in, float* out) {
  static const bool avx2 = gradient_noise_has_avx2();
  (avx2 ? gradient_noise_avx2 : gradient_noise_portable)(in, out);
}

}  // namespace maquette::texture
