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
  std::vector<Lattice> by_shift(kMaxNoiseShift + 1);
  for (int o = 0; o < field.octaves(); ++o) {
    const double wavelength = field.wavelength_m(o);
    int shift = 0;
    if (g_.pixel_m > 0) {
      if (wavelength < 2 * g_.pixel_m) continue;  // anti-aliasing: its mean, 0
      const double samples = samples_per_wavelength(field.amplitude(o) / field.norm());
      while (shift < kMaxNoiseShift && (2 << shift) * g_.pixel_m * samples <= wavelength) ++shift;
    }
    by_shift[size_t(shift)].octaves.push_back(o);
  }
  for (int shift = 0; shift <= kMaxNoiseShift; ++shift) {
    Lattice l = std::move(by_shift[size_t(shift)]);
    if (l.octaves.empty()) continue;
    l.shift = shift;
    const int spacing = 1 << shift;
    l.node_col0 = ((g_.col0 - g_.ring) >> shift) - 1;
    l.node_row0 = ((g_.row0 - g_.ring) >> shift) - 1;
    l.cols = int(((g_.col0 + g_.size + g_.ring - 1) >> shift) + 2 - l.node_col0 + 1);
    l.rows = int(((g_.row0 + g_.size + g_.ring - 1) >> shift) + 2 - l.node_row0 + 1);
    if (shift > 0)
      l.nodes.assign(size_t(l.cols) * size_t(l.rows), std::numeric_limits<float>::quiet_NaN());
    for (int t = 0; t < spacing; ++t)
      for (const double w : catmull_rom(double(t) / spacing)) l.weights.push_back(float(w));
    lattices_.push_back(std::move(l));
  }
}

void LatticeNoise::sum(const Lattice& l, const Vec3d* position, int n, float* out) const {
  std::array<float, kBatch> octave;
  std::fill(out, out + n, 0.0f);
  for (const int o : l.octaves) {
    field_.octave(o, position, n, octave.data());
    for (int k = 0; k < n; ++k) out[k] += float(field_.amplitude(o)) * octave[size_t(k)];
  }
}

const float* LatticeNoise::node_row(Lattice& l, int j, int i0, int i1) {
  float* row = &l.nodes[size_t(j) * size_t(l.cols)];
  std::array<int, kBatch> index;
  std::array<Vec3d, kBatch> position;
  std::array<float, kBatch> value;
  for (int i = i0; i <= i1;) {  // the missing nodes, a batch at a time
    int n = 0;
    for (; i <= i1 && n < kBatch; ++i)
      if (std::isnan(row[i])) {
        index[size_t(n)] = i;
        position[size_t(n++)] = g_.position->at(int(((l.node_col0 + i) << l.shift) - g_.col0),
                                                int(((l.node_row0 + j) << l.shift) - g_.row0));
      }
    sum(l, position.data(), n, value.data());
    for (int k = 0; k < n; ++k) row[index[size_t(k)]] = value[size_t(k)];
  }
  return row;
}

void LatticeNoise::row(int r, int c0, int c1, float* out) {
  if (g_.pixel_m == 0) {  // NoiseField itself
    for (int c = c0; c <= c1; ++c) out[c - c0] = field_(g_.position->at(c, r));
    return;
  }
  const size_t n = size_t(c1 - c0 + 1);
  sum_.assign(n, 0.0f);
  for (Lattice& l : lattices_) {
    if (l.shift == 0) {  // every pixel is a node
      std::array<Vec3d, kBatch> position;
      std::array<float, kBatch> value;
      for (int c = c0; c <= c1; c += kBatch) {
        const int n = std::min(kBatch, c1 - c + 1);
        for (int k = 0; k < n; ++k) position[size_t(k)] = g_.position->at(c + k, r);
        sum(l, position.data(), n, value.data());
        for (int k = 0; k < n; ++k) sum_[size_t(c - c0 + k)] += value[size_t(k)];
      }
      continue;
    }
    const int64_t mask = (int64_t(1) << l.shift) - 1, gr = g_.row0 + r;
    const float* wy = &l.weights[4 * size_t(gr & mask)];
    const int j = int((gr >> l.shift) - 1 - l.node_row0);
    const int i0 = int(((g_.col0 + c0) >> l.shift) - 1 - l.node_col0);
    const int i1 = int(((g_.col0 + c1) >> l.shift) + 2 - l.node_col0);
    vertical_.resize(size_t(i1 - i0 + 1));
    const float *n0 = node_row(l, j, i0, i1), *n1 = node_row(l, j + 1, i0, i1),
                *n2 = node_row(l, j + 2, i0, i1), *n3 = node_row(l, j + 3, i0, i1);
    const float w0 = wy[0], w1 = wy[1], w2 = wy[2], w3 = wy[3];
    float* vertical = vertical_.data();
    for (int i = i0; i <= i1; ++i)
      vertical[i - i0] = w0 * n0[i] + w1 * n1[i] + w2 * n2[i] + w3 * n3[i];
    // Pixel by pixel, a node interval at a time.
    float* s = sum_.data();
    for (int c = c0; c <= c1;) {
      const int64_t gc = g_.col0 + c;
      const float* v = &vertical[(gc >> l.shift) - 1 - l.node_col0 - i0];
      const float v0 = v[0], v1 = v[1], v2 = v[2], v3 = v[3];
      for (int64_t t = gc & mask; t <= mask && c <= c1; ++t, ++c) {
        const float* wx = &l.weights[4 * size_t(t)];
        s[c - c0] += wx[0] * v0 + wx[1] * v1 + wx[2] * v2 + wx[3] * v3;
      }
    }
  }
  const float inverse_norm = float(1 / field_.norm());
  for (size_t k = 0; k < n; ++k) out[k] = std::clamp(sum_[k] * inverse_norm, -1.0f, 1.0f);
}

}  // namespace maquette::texture
