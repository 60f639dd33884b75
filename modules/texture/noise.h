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

 private:
  float octave(double x, double y, double z) const;

  NoiseParams p_;
  std::vector<uint16_t> perm_;  // 2 x 4096
};

}  // namespace maquette::texture
