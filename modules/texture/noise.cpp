#include "noise.h"

#include <algorithm>

#include "core/splitmix64.h"

namespace maquette::texture {

NoiseField::NoiseField(const NoiseParams& params) {
  double amplitude = 1, scale = 1 / params.wavelength_m;
  uint64_t state = params.seed;
  for (int o = 0; o < params.octaves; ++o) {
    scale_.push_back(scale);
    amplitude_.push_back(amplitude);
    seed_.push_back(uint32_t(splitmix64_next(state) >> 32));
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
