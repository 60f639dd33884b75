// Noise with codomain [-1, 1] as a function of the position on the globe (metres, earth-centred
// on the authalic sphere), so tiles and faces join without seams and every level sees the same
// field. Deterministic: gradients picked by a seeded integer hash of the lattice node
// (gradient_noise.h), the same bits on every run, thread and processor.
#pragma once

#include <cstdint>
#include <vector>

#include "gradient_noise.h"
#include "model.h"

namespace maquette::texture {

// Fractal gradient noise (improved Perlin noise, each octave's lattice hashed with its own seed
// drawn from NoiseParams::seed): `octaves` octaves, each of half the wavelength and
// `persistence` times the amplitude of the previous, normalised by the sum of amplitudes and
// clamped to [-1, 1]. No period on the globe (2^32 wavelengths).
class NoiseField {
 public:
  explicit NoiseField(const NoiseParams& params);
  float operator()(const Vec3d& position_m) const;

  // The parts of operator(): octave o (0 = coarsest) at a position, in [-1, 1] before weighting,
  // its wavelength and amplitude, and the sum of the amplitudes. operator() is
  // clamp(sum_o amplitude(o) octave(o, p) / norm(), -1, 1).
  int octaves() const { return int(amplitude_.size()); }
  float octave(int o, const Vec3d& position_m) const;
  void octave(int o, Coordinates position_m, int n, float* out) const;  // at n positions
  double wavelength_m(int o) const { return 1 / scale_[size_t(o)]; }
  double amplitude(int o) const { return amplitude_[size_t(o)]; }
  double norm() const { return norm_; }

 private:
  std::vector<double> scale_, amplitude_;  // per octave: 1 / wavelength, weight
  std::vector<uint32_t> seed_;             // per octave: the hash's seed
  double norm_ = 0;
};

}  // namespace maquette::texture
