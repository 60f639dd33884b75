#include "lattice_noise.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

namespace maquette::texture {
namespace {

// Catmull-Rom weights of nodes i - 1 .. i + 2 at the fraction u of the way from node i to i + 1.
std::array<double, 4> catmull_rom(double u) {
  const double u2 = u * u, u3 = u2 * u;
  return {(-u3 + 2 * u2 - u) / 2, (3 * u3 - 5 * u2 + 2) / 2, (-3 * u3 + 4 * u2 + u) / 2,
          (u3 - u2) / 2};
}

// The largest error of one octave interpolated from k samples per wavelength, as k goes down
// (measured over 25600 points against exact evaluation).
constexpr std::array<std::pair<double, double>, 5> kOctaveError{
    {{8, 0.005}, {5.66, 0.014}, {4, 0.04}, {2.83, 0.12}, {2, 0.30}}};
constexpr double kOctaveBudget = 0.02;  // largest error an octave may add to the noise

// Samples per wavelength an octave with this share of the noise's amplitude needs.
double samples_per_wavelength(double share) {
  double k = kOctaveError[0].first;  // enough for any share
  for (const auto& [samples, error] : kOctaveError) {
    if (share * error > kOctaveBudget) break;
    k = samples;
  }
  return k;
}

}  // namespace

LatticeNoise::LatticeNoise(const NoiseField& field, const NoiseGeometry& geometry)
    : field_(field), g_(geometry) {
  for (int o = 0; o < field.octaves(); ++o) {
    const double wavelength = field.wavelength_m(o);
    Octave oc;
    oc.index = o;
    if (g_.pixel_m > 0) {
      if (wavelength < 2 * g_.pixel_m) continue;  // anti-aliasing: its mean, 0
      const double samples = samples_per_wavelength(field.amplitude(o) / field.norm());
      while (oc.shift < kMaxNoiseShift && (2 << oc.shift) * g_.pixel_m * samples <= wavelength)
        ++oc.shift;
    }
    const int spacing = 1 << oc.shift;
    oc.node_col0 = ((g_.col0 - g_.ring) >> oc.shift) - 1;
    oc.node_row0 = ((g_.row0 - g_.ring) >> oc.shift) - 1;
    oc.cols = int(((g_.col0 + g_.size + g_.ring - 1) >> oc.shift) + 2 - oc.node_col0 + 1);
    oc.rows = int(((g_.row0 + g_.size + g_.ring - 1) >> oc.shift) + 2 - oc.node_row0 + 1);
    if (oc.shift > 0)
      oc.nodes.assign(size_t(oc.cols) * size_t(oc.rows), std::numeric_limits<float>::quiet_NaN());
    for (int t = 0; t < spacing; ++t)
      for (const double w : catmull_rom(double(t) / spacing)) oc.weights.push_back(w);
    octaves_.push_back(std::move(oc));
  }
}

const Vec3d& LatticeNoise::position(int64_t col, int64_t row) const {
  const int64_t side = g_.size + 2 * g_.position_ring;
  return (*g_.position)[size_t((row + g_.position_ring) * side + col + g_.position_ring)];
}

float LatticeNoise::node(Octave& o, int i, int j) {
  float& v = o.nodes[size_t(j) * size_t(o.cols) + size_t(i)];
  if (std::isnan(v))
    v = field_.octave(o.index, position(((o.node_col0 + i) << o.shift) - g_.col0,
                                        ((o.node_row0 + j) << o.shift) - g_.row0));
  return v;
}

void LatticeNoise::row(int r, int c0, int c1, float* out) {
  const size_t n = size_t(c1 - c0 + 1);
  sum_.assign(n, 0.0);
  for (Octave& o : octaves_) {
    const double a = field_.amplitude(o.index);
    if (o.shift == 0) {  // every pixel is a node: exact
      for (int c = c0; c <= c1; ++c)
        sum_[size_t(c - c0)] += a * field_.octave(o.index, position(c, r));
      continue;
    }
    const int64_t mask = (int64_t(1) << o.shift) - 1, gr = g_.row0 + r;
    const double* wy = &o.weights[4 * size_t(gr & mask)];
    const int j = int((gr >> o.shift) - 1 - o.node_row0);
    const int i0 = int(((g_.col0 + c0) >> o.shift) - 1 - o.node_col0);
    const int i1 = int(((g_.col0 + c1) >> o.shift) + 2 - o.node_col0);
    vertical_.resize(size_t(i1 - i0 + 1));
    for (int i = i0; i <= i1; ++i) {
      double v = 0;
      for (int k = 0; k < 4; ++k) v += wy[k] * node(o, i, j + k);
      vertical_[size_t(i - i0)] = a * v;
    }
    // Pixel by pixel, a node interval at a time.
    for (int c = c0; c <= c1;) {
      const int64_t gc = g_.col0 + c;
      const double* v = &vertical_[size_t((gc >> o.shift) - 1 - o.node_col0 - i0)];
      for (int64_t t = gc & mask; t <= mask && c <= c1; ++t, ++c) {
        const double* wx = &o.weights[4 * size_t(t)];
        sum_[size_t(c - c0)] += wx[0] * v[0] + wx[1] * v[1] + wx[2] * v[2] + wx[3] * v[3];
      }
    }
  }
  for (size_t k = 0; k < n; ++k) out[k] = float(std::clamp(sum_[k] / field_.norm(), -1.0, 1.0));
}

}  // namespace maquette::texture
