// Noise with codomain [-1, 1] as a function of the position on the globe (metres, earth-centred
// on the authalic sphere), so tiles and faces join without seams and every level sees the same
// field. Deterministic: a seeded permutation table (integer hashing), the same bits on every run
// and thread.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "model.h"

namespace maquette::texture {

using Vec3d = std::array<double, 3>;

// Fractal gradient noise (improved Perlin noise over a 4096-periodic permutation table seeded
// by NoiseParams::seed): `octaves` octaves, each of half the wavelength and `persistence` times
// the amplitude of the previous, normalised by the sum of amplitudes and clamped to [-1, 1].
// The period is 4096 wavelengths of the coarsest octave (820 km at 200 m).
class NoiseField {
 public:
  explicit NoiseField(const NoiseParams& params);
  float operator()(const Vec3d& position_m) const;

  // The parts of operator(): octave o (0 = coarsest) at a position, in [-1, 1] before weighting,
  // its wavelength and amplitude, and the sum of the amplitudes. operator() is
  // clamp(sum_o amplitude(o) octave(o, p) / norm(), -1, 1).
  int octaves() const { return int(amplitude_.size()); }
  float octave(int o, const Vec3d& position_m) const;
  void octave(int o, const Vec3d* position_m, int n, float* out) const;  // at n positions
  double wavelength_m(int o) const { return 1 / scale_[size_t(o)]; }
  double amplitude(int o) const { return amplitude_[size_t(o)]; }
  double norm() const { return norm_; }

 private:
  std::vector<double> scale_, amplitude_;  // per octave: 1 / wavelength, weight
  double norm_ = 0;
  std::vector<uint16_t> perm_;  // 2 x 4096
};

}  // namespace maquette::texture
