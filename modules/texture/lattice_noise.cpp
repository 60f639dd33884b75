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
      l.row_started.assign(size_t(l.rows), 0);
    }
    for (int t = 0; t < spacing; ++t)
      for (const double w : catmull_rom(double(t) / spacing)) l.weights.push_back(float(w));
    lattices_.push_back(std::move(l));
    if (shift > 0 && !finest) finest = true, merged_ = lattices_.size();
  }
  if (!finest) merged_ = lattices_.size();
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
  if (!l.row_started[size_t(j)]) {
    std::fill(row, row + l.cols, std::numeric_limits<float>::quiet_NaN());
    l.row_started[size_t(j)] = 1;
  }
  int missing = 0;  // a test without branches first (vectorized): most rows are complete
  for (int i = i0; i <= i1; ++i) missing |= row[i] != row[i] ? 1 : 0;
  if (!missing) return row;
  while (!std::isnan(row[i0])) ++i0;
  while (!std::isnan(row[i1])) --i1;
  const int r = int(((l.node_row0 + j) << l.shift) - g_.row0);
  const auto column = [&](int i) { return int(((l.node_col0 + i) << l.shift) - g_.col0); };
  const bool finest = merged_ < lattices_.size() && &l == &lattices_[merged_ - 1];
  if (finest) {  // the coarser lattices at these nodes
    coarser_.assign(size_t(i1 - i0 + 1), 0.0f);
    for (size_t m = merged_; m < lattices_.size(); ++m)
      add_interpolated(lattices_[m], r, column(i0), column(i1), 1 << l.shift, coarser_.data());
  }
  std::array<int, kBatch> index;
  std::array<Vec3d, kBatch> position;
  std::array<float, kBatch> value;
  for (int i = i0; i <= i1;) {  // the missing nodes, a batch at a time
    int n = 0;
    for (; i <= i1 && n < kBatch; ++i)
      if (std::isnan(row[i])) {
        index[size_t(n)] = i;
        position[size_t(n++)] = g_.position->at(column(i), r);
      }
    sum(l, position.data(), n, value.data());
    for (int k = 0; k < n; ++k)
      row[index[size_t(k)]] =
          finest ? value[size_t(k)] + coarser_[size_t(index[size_t(k)] - i0)] : value[size_t(k)];
  }
  return row;
}

void LatticeNoise::add_interpolated(Lattice& l, int r, int c0, int c1, int step, float* out) {
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
  // that are multiples of step, offset by offset (loops over the intervals, vectorized), then
  // picked.
  const int intervals = i1 - i0 - 2;  // starting at nodes i0 + 1 ..
  horizontal_.resize(size_t(intervals) << l.shift);
  float* h = horizontal_.data();
  for (int t = 0; t < 1 << l.shift; t += step) {
    const float* wx = &l.weights[4 * size_t(t)];
    const float x0 = wx[0], x1 = wx[1], x2 = wx[2], x3 = wx[3];
    float* ht = h + size_t(t) * size_t(intervals);
    for (int k = 0; k < intervals; ++k)
      ht[k] = x0 * vertical[k] + x1 * vertical[k + 1] + x2 * vertical[k + 2] + x3 * vertical[k + 3];
  }
  // Pixel c lies at offset t = p & mask in interval p >> shift, p its column from the first
  // interval's node.
  const int64_t p0 = g_.col0 + c0 - ((l.node_col0 + i0 + 1) << l.shift), mask = (1 << l.shift) - 1;
  const int n = (c1 - c0) / step + 1;
  for (int k = 0; k < n; ++k) {
    const int64_t p = p0 + int64_t(k) * step;
    out[k] += h[size_t(p & mask) * size_t(intervals) + size_t(p >> l.shift)];
  }
}

void LatticeNoise::row(int r, int c0, int c1, float* out) {
  if (g_.pixel_m == 0) {  // NoiseField itself
    for (int c = c0; c <= c1; ++c) out[c - c0] = field_(g_.position->at(c, r));
    return;
  }
  const size_t n = size_t(c1 - c0 + 1);
  sum_.assign(n, 0.0f);
  for (size_t m = 0; m < merged_; ++m) {
    Lattice& l = lattices_[m];
    if (l.shift == 0) {  // every pixel is a node
      std::array<Vec3d, kBatch> position;
      std::array<float, kBatch> value;
      for (int c = c0; c <= c1; c += kBatch) {
        const int n = std::min(kBatch, c1 - c + 1);
        for (int k = 0; k < n; ++k) position[size_t(k)] = g_.position->at(c + k, r);
        sum(l, position.data(), n, value.data());
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
