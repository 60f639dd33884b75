// The inputs of the procedural model at the target resolution of one tile: the DEM (and any
// climate raster) upsampled by a uniform cubic B-spline (paper 4: bilinear gives piecewise
// linear patches), slope from the upsampled heights, and every pixel's position on the globe
// for the noise. A target tile is `refine` levels finer than the input tiles: M = size << refine
// pixels a side. Planes carry a ring of pixels beyond the tile so that slopes and normals at its
// border come from the same values its neighbours compute (no seams).
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include "core/cell_id.h"
#include "core/grid.h"
#include "core/tile.h"
#include "evaluated_spans.h"
#include "noise.h"

namespace maquette::texture {

inline constexpr int kInputHalo = 4;  // input pixels the B-spline needs around a tile (ring 2)

struct Plane {
  int size = 0, ring = 0;  // M, and the extra pixels on every side
  std::vector<float> v;
  Plane() = default;
  Plane(int size_, int ring_, float fill = 0)
      : size(size_), ring(ring_), v(size_t(size_ + 2 * ring_) * size_t(size_ + 2 * ring_), fill) {}
  int side() const { return size + 2 * ring; }
  // To `size_` and `ring_`, the values left unset (for a buffer reused and then overwritten).
  void reshape(int size_, int ring_) {
    size = size_, ring = ring_;
    v.resize(size_t(side()) * size_t(side()));
  }
  float& at(int col, int row) {
    return v[size_t(row + ring) * size_t(side()) + size_t(col + ring)];
  }
  float at(int col, int row) const {
    return v[size_t(row + ring) * size_t(side()) + size_t(col + ring)];
  }
};

// Cubic B-spline of `tile` (halo >= kInputHalo) at the target pixels of a tile `refine` levels
// finer, with `ring` (<= 2) extra pixels; NaN where a tap is NaN.
Plane upsample(const Tile<float>& tile, int refine, int ring);
void upsample(const Tile<float>& tile, int refine, int ring, Plane& out);  // reusing `out`

// Nearest neighbour of `tile` (halo >= kInputHalo) at the target pixels of a tile `refine`
// levels finer, with `ring` (<= 2) extra pixels: each target pixel takes the input pixel it lies
// in (categorical rasters, whose codes must not be blended).
void nearest(const Tile<float>& tile, int refine, int ring, Plane& out);
Plane nearest(const Tile<float>& tile, int refine, int ring);

// Slope in degrees, with one ring less than `height` (central differences over pixel_m), in
// float: the arc tangent is atan_nonnegative (vectorizable, unlike std::atan).
Plane slope_degrees(const Plane& height, double pixel_m);
void slope_degrees(const Plane& height, double pixel_m, Plane& out);  // reusing `out`

// The arc tangent of x >= 0 in float without branches (Cephes' atanf: range reduction and a
// polynomial; within 3 ulp of the exact value, tested). NaN for NaN.
// Inlined everywhere (also into the AVX2 clones, where it vectorizes 8 lanes wide).
[[gnu::always_inline]] inline float atan_nonnegative(float x) {
  constexpr float kTan3PiOver8 = 2.414213562373095f, kTanPiOver8 = 0.4142135623730950f;
  // Every candidate computed, then selected: no branch.
  const bool big = x > kTan3PiOver8, middle = x > kTanPiOver8;
  const float inverse = -1 / x, shifted = (x - 1) / (x + 1);
  const float t = big ? inverse : middle ? shifted : x;
  const float base = big ? float(M_PI_2) : middle ? float(M_PI_4) : 0.0f;
  const float z = t * t;
  const float p =
      ((8.05374449538e-2f * z - 1.38776856032e-1f) * z + 1.99777106478e-1f) * z - 3.33329491539e-1f;
  return base + (p * z * t + t);
}

// Positions (metres, on the sphere of the authalic radius) of the target pixels of `cell` and
// `ring` pixels around, computed on demand: exact on a lattice of every 8th global pixel (16th or
// 32nd for pixels of <= 9 m), bilinear in between, so neighbouring tiles compute the same values
// for the same pixel. Only the lattice is stored, and the rows the noise asked for lately (it
// needs positions at its own lattice nodes, rarely at every pixel).
class PixelPositions {
 public:
  PixelPositions(const Grid& grid, CellId cell, int size, int refine, int ring);
  // Of target pixel (col, row), -ring <= col, row < M + ring.
  Vec3d at(int col, int row) const;
  // Of target pixels (col0 + k step, row), k < n, into out[axis][k]: the same bits as at() (the
  // same formula per pixel), vectorized; the noise's lattice nodes along a node row.
  void along_row(int col0, int step, int n, int row, const std::array<double*, 3>& out) const;
  // The same positions, computed once and kept for the next calls with the same row, step and
  // phase (the layers of a tile ask for the same noise lattice nodes in turn; the last 8 rows of
  // each step are kept). step: 1, 2, 4 or 8. Valid until the next call; one thread at a time.
  Coordinates along_row_kept(int col0, int step, int n, int row) const;

 private:
  // Bilinear between the values a0, a1 (nodes above) and b0, b1 (below) at fractions fx, fy of
  // the way across: at() and along_row() share it, so they give the same bits.
  [[gnu::always_inline]] static double bilinear(double a0, double a1, double b0, double b1,
                                                double fx, double fy) {
    return (1 - fy) * ((1 - fx) * a0 + fx * a1) + fy * ((1 - fx) * b0 + fx * b1);
  }

  static constexpr int kMaxNodeSpacing = 32;
  int shift_ = 3;              // node spacing 2^shift pixels
  int64_t gc0_ = 0, gr0_ = 0;  // global face pixel of target pixel (0, 0)
  int64_t nc0_ = 0, nr0_ = 0;  // global node coordinates of node[0]
  int nodes_ = 0;              // a side
  std::vector<Vec3d> node_;
  int m_ = 0, ring_ = 0;

  // Rows of along_row_kept(): position[i] is that of pixel (first + i step, row), known where
  // `computed` says.
  struct KeptRow {
    int row = 0, step = 0, first = 0;  // step 0: none
    EvaluatedSpans computed;
    Points position;
  };
  static constexpr int kKeptRows = 8;                // per step, by row mod 8
  mutable std::array<KeptRow, 4 * kKeptRows> kept_;  // steps 1, 2, 4, 8
};

inline Vec3d PixelPositions::at(int col, int row) const {
  const int64_t gc = gc0_ + col, gr = gr0_ + row, mask = (int64_t(1) << shift_) - 1;
  const double inverse_step = 1 / double(mask + 1),  // exact: a power of two
      fx = double(gc & mask) * inverse_step, fy = double(gr & mask) * inverse_step;
  const Vec3d* n =
      &node_[size_t((gr >> shift_) - nr0_) * size_t(nodes_) + size_t((gc >> shift_) - nc0_)];
  Vec3d p;
  const Vec3d* b = n + nodes_;
  for (size_t k = 0; k < 3; ++k) p[k] = bilinear(n[0][k], n[1][k], b[0][k], b[1][k], fx, fy);
  return p;
}

}  // namespace maquette::texture
