#include "noise.h"

#include <algorithm>
#include <cmath>

namespace maquette::texture {
namespace {

constexpr int kPeriod = 4096;

uint64_t splitmix(uint64_t& state) {
  uint64_t x = (state += 0x9E3779B97F4A7C15ULL);
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// Dot product of one of the 12 cube-edge gradients (Perlin 2002; 16 cases, 4 repeated) with
// (x, y, z). A table rather than branches: the hashed case is unpredictable.
constexpr float kGrad[16][3] = {
    {1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0}, {1, 0, 1}, {-1, 0, 1}, {1, 0, -1}, {-1, 0, -1},
    {0, 1, 1}, {0, -1, 1}, {0, 1, -1}, {0, -1, -1}, {1, 1, 0}, {0, -1, 1}, {-1, 1, 0}, {0, -1, -1}};

float grad(unsigned h, float x, float y, float z) {
  const float* g = kGrad[h & 15];
  return g[0] * x + g[1] * y + g[2] * z;
}

float fade(float t) { return t * t * t * (t * (t * 6 - 15) + 10); }
float lerp(float a, float b, float t) { return a + t * (b - a); }

}  // namespace

NoiseField::NoiseField(const NoiseParams& params) : perm_(2 * kPeriod) {
  double amplitude = 1, scale = 1 / params.wavelength_m;
  for (int o = 0; o < params.octaves; ++o) {
    scale_.push_back(scale);
    amplitude_.push_back(amplitude);
    norm_ += amplitude;
    amplitude *= params.persistence;
    scale *= 2;
  }
  for (int i = 0; i < kPeriod; ++i) perm_[size_t(i)] = uint16_t(i);
  uint64_t state = params.seed;
  for (int i = kPeriod - 1; i > 0; --i)  // Fisher-Yates
    std::swap(perm_[size_t(i)], perm_[size_t(splitmix(state) % uint64_t(i + 1))]);
  std::copy(perm_.begin(), perm_.begin() + kPeriod, perm_.begin() + kPeriod);
}

// Gradient noise at N points, stage by stage across the points: the hashed lookups of all the
// points first, then their arithmetic, which gives the processor independent work to overlap
// (texture_benchmark: ~5% faster overall than point by point; the arithmetic on arrays, which GCC
// then vectorizes, was no faster). The same operations per point whatever N: the same bits.
template <int N>
void gradient_noise(const uint16_t* P, const double* x, const double* y, const double* z,
                    float* out) {
  float dx[N], dy[N], dz[N];
  unsigned h[8][N];
  for (int n = 0; n < N; ++n) {
    const double fx = std::floor(x[n]), fy = std::floor(y[n]), fz = std::floor(z[n]);
    const auto i = unsigned(int64_t(fx) & (kPeriod - 1)), j = unsigned(int64_t(fy) & (kPeriod - 1)),
               k = unsigned(int64_t(fz) & (kPeriod - 1));
    dx[n] = float(x[n] - fx), dy[n] = float(y[n] - fy), dz[n] = float(z[n] - fz);
    const unsigned a = P[i] + j, aa = P[a] + k, ab = P[a + 1] + k;
    const unsigned b = P[i + 1] + j, ba = P[b] + k, bb = P[b + 1] + k;
    h[0][n] = P[aa], h[1][n] = P[ba], h[2][n] = P[ab], h[3][n] = P[bb];
    h[4][n] = P[aa + 1], h[5][n] = P[ba + 1], h[6][n] = P[ab + 1], h[7][n] = P[bb + 1];
  }
  for (int n = 0; n < N; ++n) {
    const float X = dx[n], Y = dy[n], Z = dz[n];
    const float u = fade(X), v = fade(Y), w = fade(Z);
    out[n] =
        lerp(lerp(lerp(grad(h[0][n], X, Y, Z), grad(h[1][n], X - 1, Y, Z), u),
                  lerp(grad(h[2][n], X, Y - 1, Z), grad(h[3][n], X - 1, Y - 1, Z), u), v),
             lerp(lerp(grad(h[4][n], X, Y, Z - 1), grad(h[5][n], X - 1, Y, Z - 1), u),
                  lerp(grad(h[6][n], X, Y - 1, Z - 1), grad(h[7][n], X - 1, Y - 1, Z - 1), u), v),
             w);
  }
}

void NoiseField::octave(int o, const Vec3d* p, int n, float* out) const {
  constexpr int kLanes = 4;  // points per gradient_noise call (8 was no faster)
  // Octaves shifted apart so their lattices do not line up.
  const double scale = scale_[size_t(o)], shift = 0.37 * o;
  for (int first = 0; first < n; first += kLanes) {
    const int lanes = std::min(kLanes, n - first);
    double x[kLanes], y[kLanes], z[kLanes];
    for (int k = 0; k < lanes; ++k) {
      const Vec3d& q = p[first + k];
      x[k] = q[0] * scale + shift, y[k] = q[1] * scale + 2 * shift, z[k] = q[2] * scale + 3 * shift;
    }
    if (lanes == kLanes)
      gradient_noise<kLanes>(perm_.data(), x, y, z, out + first);
    else
      for (int k = 0; k < lanes; ++k)
        gradient_noise<1>(perm_.data(), x + k, y + k, z + k, out + first + k);
  }
}

float NoiseField::octave(int o, const Vec3d& p) const {
  float v;
  octave(o, &p, 1, &v);
  return v;
}

float NoiseField::operator()(const Vec3d& p) const {
  double sum = 0;
  for (int o = 0; o < octaves(); ++o) sum += amplitude_[size_t(o)] * octave(o, p);
  return float(std::clamp(sum / norm_, -1.0, 1.0));
}

}  // namespace maquette::texture
