// Seeded 3D gradient noise (Perlin 2002's 12 edge gradients, quintic fade) at many points: a
// portable path and an AVX2 path (8 points at a time) that give the same bits, chosen once by
// what the processor supports. The gradient of a lattice node is picked by an integer hash of
// its coordinates and the seed (multiply-xorshift, so it vectorizes without table lookups).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace maquette::texture {

using Vec3d = std::array<double, 3>;

// Points as one array of coordinates per axis (point k is (x[k], y[k], z[k])), so that the
// kernel loads an axis of 4 points as one vector.
using Coordinates = std::array<const double*, 3>;

// The points from the k-th on.
inline Coordinates advanced(const Coordinates& p, size_t k) {
  return {p[0] + k, p[1] + k, p[2] + k};
}

// Points stored that way.
struct Points {
  std::array<std::vector<double>, 3> axis;

  size_t size() const { return axis[0].size(); }
  void resize(size_t n) {
    for (std::vector<double>& a : axis) a.resize(n);
  }
  void push_back(const Vec3d& p) {
    for (size_t a = 0; a < 3; ++a) axis[a].push_back(p[a]);
  }
  Coordinates from(size_t k) const {
    return advanced({axis[0].data(), axis[1].data(), axis[2].data()}, k);
  }
  std::array<double*, 3> to(size_t k) { return {&axis[0][k], &axis[1][k], &axis[2][k]}; }
};

// Noise in [-1, 1] at the n points position * scale + offset (lattice units: one node per unit,
// period 2^32 along each axis; coordinates below 2^51 in magnitude), into out[0 .. n - 1].
struct GradientNoiseInput {
  Coordinates position{};
  int n = 0;
  double scale = 1;
  Vec3d offset{};
  uint32_t seed = 0;
};

void gradient_noise(const GradientNoiseInput& in, float* out);  // the best path available

// The two paths, callable explicitly (the test compares their bits). The AVX2 path needs
// gradient_noise_has_avx2().
void gradient_noise_portable(const GradientNoiseInput& in, float* out);
bool gradient_noise_has_avx2();
void gradient_noise_avx2(const GradientNoiseInput& in, float* out);

}  // namespace maquette::texture
