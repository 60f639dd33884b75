#include "field.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>

#include "core/avx2_clones.h"
#include "core/error.h"
#include "core/halo.h"

namespace maquette::texture {
namespace {

constexpr double kAuthalicRadius = 6371007.180918;

// Uniform cubic B-spline weights of taps i-1 .. i+2 at fraction f (exact in double, then
// rounded: the sums are in float).
std::array<float, 4> bspline_weights(double f) {
  const double f2 = f * f, f3 = f2 * f;
  return {float((1 - f) * (1 - f) * (1 - f) / 6), float((3 * f3 - 6 * f2 + 4) / 6),
          float((-3 * f3 + 3 * f2 + 3 * f + 1) / 6), float(f3 / 6)};
}

struct Taps {
  int first = 0;  // input pixel of the first tap
  std::array<float, 4> w{};
};

// Target pixel t (of a tile 2^refine times finer) -> input taps; input pixel centres are at
// integer coordinates, target pixel centres at (t + 0.5) / 2^refine - 0.5.
Taps taps(int t, int refine) {
  const double u = (t + 0.5) / double(1 << refine) - 0.5, i = std::floor(u);
  return {int(i) - 1, bspline_weights(u - i)};
}

}  // namespace

// In float (heights to a fraction of a millimetre), vectorized for AVX2 where the CPU has it
// (the same operations, so the same bits).
MAQUETTE_AVX2_CLONES void upsample(const Tile<float>& tile, int refine, int ring, Plane& out) {
  const int m = tile.size() << refine;
  if (tile.halo() < kInputHalo)
    throw Error("texture: input tiles need a halo of " + std::to_string(kInputHalo) + " pixels");
  out.reshape(m, ring);
  const size_t side = size_t(out.side());
  std::vector<Taps> t(side);
  for (size_t i = 0; i < side; ++i) t[i] = taps(int(i) - ring, refine);
  // Separable: rows of the input first (at target columns), then columns.
  const int rows0 = t.front().first, rows1 = t.back().first + 4;
  thread_local std::vector<float> horizontal;  // reused, every value written
  horizontal.resize(size_t(rows1 - rows0) * side);
  // The target columns c of the same phase c mod 2^refine share the weights, their taps step
  // by one input pixel: a loop per phase (vectorized).
  const size_t phases = std::min(size_t(1) << refine, side);
  const int cols0 = t.front().first, cols1 = t.back().first + 4;
  thread_local std::vector<float> input;  // the row's first channel
  input.resize(size_t(cols1 - cols0));
  for (int r = rows0; r < rows1; ++r) {
    for (int i = cols0; i < cols1; ++i) input[size_t(i - cols0)] = tile.at(i, r);
    float* h = &horizontal[size_t(r - rows0) * side];
    for (size_t p = 0; p < phases; ++p) {
      const float w0 = t[p].w[0], w1 = t[p].w[1], w2 = t[p].w[2], w3 = t[p].w[3];
      const float* x = &input[size_t(t[p].first - cols0)];
      const size_t count = (side - p + phases - 1) / phases;
      for (size_t j = 0; j < count; ++j)
        h[p + j * phases] = w0 * x[j] + w1 * x[j + 1] + w2 * x[j + 2] + w3 * x[j + 3];
    }
  }
  for (size_t r = 0; r < side; ++r) {
    const Taps& tr = t[r];
    const float* h0 = &horizontal[size_t(tr.first - rows0) * side];
    const float *h1 = h0 + side, *h2 = h1 + side, *h3 = h2 + side;
    const float w0 = tr.w[0], w1 = tr.w[1], w2 = tr.w[2], w3 = tr.w[3];
    float* o = &out.v[r * side];
    for (size_t c = 0; c < side; ++c)  // NaN taps propagate
      o[c] = w0 * h0[c] + w1 * h1[c] + w2 * h2[c] + w3 * h3[c];
  }
}

Plane upsample(const Tile<float>& tile, int refine, int ring) {
  Plane out;
  upsample(tile, refine, ring, out);
  return out;
}

void nearest(const Tile<float>& tile, int refine, int ring, Plane& out) {
  if (tile.halo() < kInputHalo)
    throw Error("texture: input tiles need a halo of " + std::to_string(kInputHalo) + " pixels");
  out.reshape(tile.size() << refine, ring);
  for (int r = -ring; r < out.size + ring; ++r)
    for (int c = -ring; c < out.size + ring; ++c)
      out.at(c, r) = tile.at(c >> refine, r >> refine);  // floor division, also below 0
}

Plane nearest(const Tile<float>& tile, int refine, int ring) {
  Plane out;
  nearest(tile, refine, ring, out);
  return out;
}

// In float, vectorized for AVX2 where the CPU has it (the same operations, so the same bits).
MAQUETTE_AVX2_CLONES void slope_degrees(const Plane& h, double pixel_m, Plane& s) {
  s.reshape(h.size, h.ring - 1);
  const float k = float(1 / (2 * pixel_m)), deg = float(180 / M_PI);
  const size_t side = size_t(s.side()), h_side = size_t(h.side());
  for (size_t r = 0; r < side; ++r) {
    const float* mid = &h.v[(r + 1) * h_side + 1];
    const float *up = mid - h_side, *down = mid + h_side, *left = mid - 1, *right = mid + 1;
    float* out = &s.v[r * side];
    for (size_t c = 0; c < side; ++c) {
      const float gx = (right[c] - left[c]) * k;
      const float gy = (down[c] - up[c]) * k;
      out[c] = atan_nonnegative(std::sqrt(gx * gx + gy * gy)) * deg;  // not hypot: slow
    }
  }
}

Plane slope_degrees(const Plane& h, double pixel_m) {
  Plane s;
  slope_degrees(h, pixel_m, s);
  return s;
}

PixelPositions::PixelPositions(const Grid& grid, CellId cell, int size, int refine, int ring) {
  const int m = size << refine;
  const int level = cell.level() + log2_tile_size(m);
  // Exact every 8th pixel, or 16th or 32nd while that spans <= 300 m (bilinear positions then
  // deviate from the true ones by centimetres at most): the projection is the costly part.
  while ((1 << shift_) < kMaxNodeSpacing &&
         (2 << shift_) * grid.level_info(level, 1).pixel_m <= 300)
    ++shift_;
  const int step = 1 << shift_;
  m_ = m;
  ring_ = ring;
  gc0_ = int64_t(cell.col()) * m;
  gr0_ = int64_t(cell.row()) * m;
  nc0_ = (gc0_ - ring) >> shift_;
  nr0_ = (gr0_ - ring) >> shift_;
  nodes_ = (m + 2 * ring) / step + 3;
  node_.resize(size_t(nodes_) * size_t(nodes_));
  for (int j = 0; j < nodes_; ++j)
    for (int i = 0; i < nodes_; ++i) {
      const int64_t lc = (nc0_ + i) * step - gc0_, lr = (nr0_ + j) * step - gr0_;
      const std::optional<FaceCoord> src = pixel_source(grid, cell, m, int(lc), int(lr));
      if (!src) throw Error("texture: tile " + cell.ToText() + " too small for its noise lattice");
      const LonLat p = pixel_centre(grid, *src, level);
      const double lat = p.lat * M_PI / 180, lon = p.lon * M_PI / 180;
      node_[size_t(j) * size_t(nodes_) + size_t(i)] = {
          kAuthalicRadius * std::cos(lat) * std::cos(lon),
          kAuthalicRadius * std::cos(lat) * std::sin(lon), kAuthalicRadius * std::sin(lat)};
    }
}

// Vectorized for AVX2 where the CPU has it (the same operations, so the same bits): the pixels
// of one lattice cell at a time, whose 4 nodes are then constant, a coordinate at a time.
MAQUETTE_AVX2_CLONES void PixelPositions::along_row(int col0, int step, int n, int row,
                                                    const std::array<double*, 3>& out) const {
  const int64_t gr = gr0_ + row, mask = (int64_t(1) << shift_) - 1;
  const double inverse_step = 1 / double(mask + 1);  // exact: a power of two
  const double fy = double(gr & mask) * inverse_step;
  const Vec3d* above = &node_[size_t((gr >> shift_) - nr0_) * size_t(nodes_)];
  std::array<double, kMaxNodeSpacing> fx;
  for (int k = 0; k < n;) {
    const int64_t gc = gc0_ + col0 + int64_t(k) * step;
    const Vec3d *a = above + ((gc >> shift_) - nc0_), *b = a + nodes_;
    const int first = int(gc & mask), count = std::min(n - k, int(mask - first) / step + 1);
    for (int j = 0; j < count; ++j) fx[size_t(j)] = double(first + j * step) * inverse_step;
    for (size_t c = 0; c < 3; ++c) {
      const double a0 = a[0][c], a1 = a[1][c], b0 = b[0][c], b1 = b[1][c];
      double* o = out[c] + k;
      for (int j = 0; j < count; ++j) o[j] = bilinear(a0, a1, b0, b1, fx[size_t(j)], fy);
    }
    k += count;
  }
}

Coordinates PixelPositions::along_row_kept(int col0, int step, int n, int row) const {
  const int shift = std::countr_zero(unsigned(step));
  if (step != 1 << shift || shift > 3)
    throw Error("texture: positions kept at steps 1, 2, 4 and 8, not " + std::to_string(step));
  KeptRow& k = kept_[size_t(shift * kKeptRows + (row & (kKeptRows - 1)))];
  const int first = col0 - (col0 + ring_) / step * step;  // the row's first pixel in phase
  if (k.step != step || k.row != row || k.first != first) {
    k = {row, step, first, {}, std::move(k.position)};
    k.position.resize(size_t((m_ + ring_ - 1 - first) / step + 1));
  }
  const int i0 = (col0 - first) / step;
  k.computed.fill(i0, i0 + n - 1, [&](int a, int b) {
    along_row(first + a * step, step, b - a + 1, row, k.position.to(size_t(a)));
  });
  return k.position.from(size_t(i0));
}

}  // namespace maquette::texture
