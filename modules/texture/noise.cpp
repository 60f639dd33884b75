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

float NoiseField::gradient_noise(double x, double y, double z) const {
  const double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
  const auto i = unsigned(int64_t(fx) & (kPeriod - 1)), j = unsigned(int64_t(fy) & (kPeriod - 1)),
             k = unsigned(int64_t(fz) & (kPeriod - 1));
  const float dx = float(x - fx), dy = float(y - fy), dz = float(z - fz);
  const float u = fade(dx), v = fade(dy), w = fade(dz);
  const uint16_t* P = perm_.data();
  const unsigned a = P[i] + j, aa = P[a] + k, ab = P[a + 1] + k;
  const unsigned b = P[i + 1] + j, ba = P[b] + k, bb = P[b + 1] + k;
  return lerp(
      lerp(lerp(grad(P[aa], dx, dy, dz), grad(P[ba], dx - 1, dy, dz), u),
           lerp(grad(P[ab], dx, dy - 1, dz), grad(P[bb], dx - 1, dy - 1, dz), u), v),
      lerp(lerp(grad(P[aa + 1], dx, dy, dz - 1), grad(P[ba + 1], dx - 1, dy, dz - 1), u),
           lerp(grad(P[ab + 1], dx, dy - 1, dz - 1), grad(P[bb + 1], dx - 1, dy - 1, dz - 1), u),
           v),
      w);
}

float NoiseField::octave(int o, const Vec3d& p) const {
  // Octaves shifted apart so their lattices do not line up.
  const double scale = scale_[size_t(o)], shift = 0.37 * o;
  return gradient_noise(p[0] * scale + shift, p[1] * scale + 2 * shift, p[2] * scale + 3 * shift);
}

float NoiseField::operator()(const Vec3d& p) const {
  double sum = 0;
  for (int o = 0; o < octaves(); ++o) sum += amplitude_[size_t(o)] * octave(o, p);
  return float(std::clamp(sum / norm_, -1.0, 1.0));
}

}  // namespace maquette::texture
