#include "synthetic_terrain.h"

#include <algorithm>
#include <cmath>

#include "core/splitmix64.h"

namespace maquette::terrain {
namespace {

constexpr double kAuthalicRadius = 6371007.180918;

uint64_t hash(int64_t x, int64_t y, int64_t z, uint64_t seed) {
  return splitmix64_mix(
      splitmix64_mix(splitmix64_mix(splitmix64_mix(seed) ^ uint64_t(x)) ^ uint64_t(y)) ^
      uint64_t(z));
}

// Dot product of the lattice point's pseudo-random gradient (one of the 12 cube edge
// directions, as in Perlin's improved noise) with the offset (x, y, z).
double gradient_dot(uint64_t h, double x, double y, double z) {
  switch (h % 12) {
    case 0:
      return x + y;
    case 1:
      return -x + y;
    case 2:
      return x - y;
    case 3:
      return -x - y;
    case 4:
      return x + z;
    case 5:
      return -x + z;
    case 6:
      return x - z;
    case 7:
      return -x - z;
    case 8:
      return y + z;
    case 9:
      return -y + z;
    case 10:
      return y - z;
    default:
      return -y - z;
  }
}

double fade(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }
double lerp(double a, double b, double t) { return a + t * (b - a); }

// 3D gradient noise, about [-1, 1].
double noise(const Vec3& p, uint64_t seed) {
  const double fx = std::floor(p[0]), fy = std::floor(p[1]), fz = std::floor(p[2]);
  const auto ix = int64_t(fx), iy = int64_t(fy), iz = int64_t(fz);
  const double x = p[0] - fx, y = p[1] - fy, z = p[2] - fz;
  double corner[8];
  for (int k = 0; k < 8; ++k) {
    const int dx = k & 1, dy = (k >> 1) & 1, dz = k >> 2;
    corner[k] = gradient_dot(hash(ix + dx, iy + dy, iz + dz, seed), x - dx, y - dy, z - dz);
  }
  const double u = fade(x), v = fade(y), w = fade(z);
  return lerp(lerp(lerp(corner[0], corner[1], u), lerp(corner[2], corner[3], u), v),
              lerp(lerp(corner[4], corner[5], u), lerp(corner[6], corner[7], u), v), w);
}

// Fractal sums over octaves (frequency x2, weight x0.5), normalised by the total weight:
// plain (about [-1, 1]) and ridged (sharp crests where the noise crosses zero, [0, 1]).
template <typename Shape>
double fractal(const Vec3& p, int octaves, uint64_t seed, Shape shape) {
  double sum = 0, weight = 1, total = 0, frequency = 1;
  for (int o = 0; o < octaves; ++o) {
    const Vec3 q{p[0] * frequency, p[1] * frequency, p[2] * frequency};
    sum += weight * shape(noise(q, seed + uint64_t(o)));
    total += weight;
    weight *= 0.5, frequency *= 2;
  }
  return sum / total;
}

double smoothstep(double e0, double e1, double x) {
  const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3 - 2 * t);
}

}  // namespace

double synthetic_elevation(const Vec3& up, const TerrainParams& params) {
  // One lattice unit per feature wavelength on the globe's surface.
  const double k = kAuthalicRadius / (params.feature_km * 1000);
  const Vec3 p{up[0] * k, up[1] * k, up[2] * k};
  const uint64_t seed = splitmix64_mix(uint64_t(params.seed));
  const double continents = 2 * fractal(p, params.octaves, seed, [](double n) { return n; });
  // Mountain ranges with ridges, inland only.
  const Vec3 q{2 * p[0] + 17.5, 2 * p[1] - 3.25, 2 * p[2] + 9.75};
  const double ridges = fractal(q, params.octaves, ~seed,
                                [](double n) { return (1 - std::abs(n)) * (1 - std::abs(n)); });
  const double relief = continents + 0.8 * ridges * smoothstep(0.0, 0.4, continents);
  return std::max(0.0, params.amplitude_m * relief);
}

}  // namespace maquette::terrain
