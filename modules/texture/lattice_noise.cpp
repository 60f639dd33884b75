#include "lattice_noise.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "core/avx2_clones.h"

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

// The node intervals 0 .. intervals - 1 of a row of vertically interpolated nodes (interval k
// from vertical[k + 1] to vertical[k + 2]) at the offsets 0, step, .. < P step from their first
// node, into h in pixel order: h[k P + t] at offset t step.
template <int P>
[[gnu::always_inline]] inline void interpolate_along(const std::vector<float>& weights, int step,
                                                     const float* vertical, int intervals,
                                                     float* h) {
  float x[P][4];
  for (int t = 0; t < P; ++t)
    for (int i = 0; i < 4; ++i) x[t][i] = weights[4 * size_t(t * step) + size_t(i)];
  for (int k = 0; k < intervals; ++k)
    for (int t = 0; t < P; ++t)
      h[k * P + t] = x[t][0] * vertical[k] + x[t][1] * vertical[k + 1] + x[t][2] * vertical[k + 2] +
                     x[t][3] * vertical[k + 3];
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
  bool finest = false;  // the finest lattice of spacing >= 2 made: the next ones merge into it
  for (int shift = 0; shift <= kMaxNoiseShift; ++shift) {
    Lattice l = std::move(by_shift[size_t(shift)]);
    if (l.octaves.empty()) continue;
    l.shift = shift;
    const int spacing = 1 << shift;
    // The nodes the pixels' interpolation needs, one more on each side for a merged lattice
    // (interpolated at the finest lattice's nodes, up to a finer spacing beyond the pixels).
    const int margin = finest ? 2 : 1;
    l.node_col0 = ((g_.col0 - g_.ring) >> shift) - margin;
    l.node_row0 = ((g_.row0 - g_.ring) >> shift) - margin;
    l.cols = int(((g_.col0 + g_.size + g_.ring - 1) >> shift) + 1 + margin - l.node_col0 + 1);
    l.rows = int(((g_.row0 + g_.size + g_.ring - 1) >> shift) + 1 + margin - l.node_row0 + 1);
    if (shift > 0) {
      l.nodes = std::make_unique_for_overwrite<float[]>(size_t(l.cols) * size_t(l.rows));
      l.evaluated.assign(size_t(l.rows), EvaluatedSpans{});
    }
    for (int t = 0; t < spacing; ++t)
      for (const double w : catmull_rom(double(t) / spacing)) l.weights.push_back(float(w));
    lattices_.push_back(std::move(l));
    if (shift > 0 && !finest) finest = true, merged_ = lattices_.size();
  }
  if (!finest) merged_ = lattices_.size();
}

void LatticeNoise::sum(const Lattice& l, Coordinates position, int n, float* out) const {
  std::array<float, kBatch> octave;
  std::fill(out, out + n, 0.0f);
  for (const int o : l.octaves) {
    field_.octave(o, position, n, octave.data());
    for (int k = 0; k < n; ++k) out[k] += float(field_.amplitude(o)) * octave[size_t(k)];
  }
}

const float* LatticeNoise::node_row(Lattice& l, int j, int i0, int i1) {
  float* row = &l.nodes[size_t(j) * size_t(l.cols)];
  l.evaluated[size_t(j)].fill(i0, i1, [&](int a, int b) { evaluate_nodes(l, j, a, b, row); });
  return row;
}

void LatticeNoise::evaluate_nodes(Lattice& l, int j, int i0, int i1, float* row) {
  const int r = int(((l.node_row0 + j) << l.shift) - g_.row0);
  const auto column = [&](int i) { return int(((l.node_col0 + i) << l.shift) - g_.col0); };
  const bool finest = merged_ < lattices_.size() && &l == &lattices_[merged_ - 1];
  if (finest) {  // the coarser lattices at these nodes
    coarser_.assign(size_t(i1 - i0 + 1), 0.0f);
    for (size_t m = merged_; m < lattices_.size(); ++m)
      add_interpolated(lattices_[m], r, column(i0), column(i1), 1 << l.shift, coarser_.data());
  }
  // Their positions at once, the noise a batch at a time.
  const Coordinates position =
      g_.position->along_row_kept(column(i0), 1 << l.shift, i1 - i0 + 1, r);
  std::array<float, kBatch> value;
  for (int i = i0; i <= i1; i += kBatch) {
    const int n = std::min(kBatch, i1 - i + 1);
    sum(l, advanced(position, size_t(i - i0)), n, value.data());
    for (int k = 0; k < n; ++k)
      row[i + k] = finest ? value[size_t(k)] + coarser_[size_t(i + k - i0)] : value[size_t(k)];
  }
}

// Vectorized for AVX2 where the CPU has it (the same operations, so the same bits).
MAQUETTE_AVX2_CLONES void LatticeNoise::add_interpolated(Lattice& l, int r, int c0, int c1,
                                                         int step, float* out) {
  const int64_t gr = g_.row0 + r;
  const float* wy = &l.weights[4 * size_t(gr & ((int64_t(1) << l.shift) - 1))];
  const int j = int((gr >> l.shift) - 1 - l.node_row0);
  const int i0 = int(((g_.col0 + c0) >> l.shift) - 1 - l.node_col0);
  const int i1 = int(((g_.col0 + c1) >> l.shift) + 2 - l.node_col0);
  const float *n0 = node_row(l, j, i0, i1), *n1 = node_row(l, j + 1, i0, i1),
              *n2 = node_row(l, j + 2, i0, i1), *n3 = node_row(l, j + 3, i0, i1);
  const float w0 = wy[0], w1 = wy[1], w2 = wy[2], w3 = wy[3];
  vertical_.resize(size_t(i1 - i0 + 1));
  float* vertical = vertical_.data();
  for (int i = i0; i <= i1; ++i)
    vertical[i - i0] = w0 * n0[i] + w1 * n1[i] + w2 * n2[i] + w3 * n3[i];
  // Along the row: the whole node intervals that c0 .. c1 touch, at the offsets from their node
  // that are multiples of step, in pixel order (offset by offset: loops over the intervals,
  // vectorized), then the pixels c0 .. c1 added.
  const int intervals = i1 - i0 - 2;  // starting at nodes i0 + 1 ..
  const int per_interval = (1 << l.shift) / step;
  horizontal_.resize(size_t(intervals) * size_t(per_interval));
  float* h = horizontal_.data();
  switch (per_interval) {  // a power of two <= 8; a constant stride, so the loops vectorize
    case 1:
      interpolate_along<1>(l.weights, step, vertical, intervals, h);
      break;
    case 2:
      interpolate_along<2>(l.weights, step, vertical, intervals, h);
      break;
    case 4:
      interpolate_along<4>(l.weights, step, vertical, intervals, h);
      break;
    default:
      interpolate_along<8>(l.weights, step, vertical, intervals, h);
      break;
  }
  // Pixel c0 lies p0 pixels from the first interval's node (p0 a multiple of step).
  const int64_t p0 = g_.col0 + c0 - ((l.node_col0 + i0 + 1) << l.shift);
  const float* from = h + p0 / step;
  const int n = (c1 - c0) / step + 1;
  for (int k = 0; k < n; ++k) out[k] += from[k];
}

MAQUETTE_AVX2_CLONES void LatticeNoise::row(int r, int c0, int c1, float* out) {
  if (g_.pixel_m == 0) {  // NoiseField itself
    for (int c = c0; c <= c1; ++c) out[c - c0] = field_(g_.position->at(c, r));
    return;
  }
  const size_t n = size_t(c1 - c0 + 1);
  sum_.assign(n, 0.0f);
  for (size_t m = 0; m < merged_; ++m) {
    Lattice& l = lattices_[m];
    if (l.shift == 0) {  // every pixel is a node
      const Coordinates position = g_.position->along_row_kept(c0, 1, int(n), r);
      std::array<float, kBatch> value;
      for (int c = c0; c <= c1; c += kBatch) {
        const int n = std::min(kBatch, c1 - c + 1);
        sum(l, advanced(position, size_t(c - c0)), n, value.data());
        for (int k = 0; k < n; ++k) sum_[size_t(c - c0 + k)] += value[size_t(k)];
      }
    } else {
      add_interpolated(l, r, c0, c1, 1, sum_.data());
    }
  }
  const float inverse_norm = float(1 / field_.norm());
  for (size_t k = 0; k < n; ++k) out[k] = std::clamp(sum_[k] * inverse_norm, -1.0f, 1.0f);
}

}  // namespace maquette::texture
