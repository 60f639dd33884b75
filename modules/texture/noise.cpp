#include "noise.h"

#include <algorithm>

namespace maquette::texture {
namespace {

uint64_t splitmix(uint64_t& state) {
  uint64_t x = (state += 0x9E3779B97F4A7C15ULL);
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

}  // namespace

NoiseField::NoiseField(const NoiseParams& params) {
  double amplitude = 1, scale = 1 / params.wavelength_m;
  uint64_t state = params.seed;
  for (int o = 0; o < params.octaves; ++o) {
    scale_.push_back(scale);
    amplitude_.push_back(amplitude);
    seed_.push_back(uint32_t(splitmix(state) >> 32));
    norm_ += amplitude;
    amplitude *= params.persistence;
    scale *= 2;
  }
}

void NoiseField::octave(int o, Coordinates p, int n, float* out) const {
  // Octaves shifted apart so their lattices do not line up.
  const double shift = 0.37 * o;
  gradient_noise({p, n, scale_[size_t(o)], {shift, 2 * shift, 3 * shift}, seed_[size_t(o)]}, out);
}

float NoiseField::octave(int o, const Vec3d& p) const {
  float v;
  octave(o, {&p[0], &p[1], &p[2]}, 1, &v);
  return v;
}

float NoiseField::operator()(const Vec3d& p) const {
  double sum = 0;
  for (int o = 0; o < octaves(); ++o) sum += amplitude_[size_t(o)] * octave(o, p);
  return float(std::clamp(sum / norm_, -1.0, 1.0));
}

}  // namespace maquette::texture
