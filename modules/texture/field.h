// The inputs of the procedural model at the target resolution of one tile: the DEM (and any
// climate raster) upsampled by a uniform cubic B-spline (paper 4: bilinear gives piecewise
// linear patches), slope from the upsampled heights, and every pixel's position on the globe
// for the noise. A target tile is `refine` levels finer than the input tiles: M = size << refine
// pixels a side. Planes carry a ring of pixels beyond the tile so that slopes and normals at its
// border come from the same values its neighbours compute (no seams).
#pragma once

#include <cmath>
#include <vector>

#include "core/cell_id.h"
#include "core/grid.h"
#include "core/tile.h"
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

// Slope in degrees, with one ring less than `height` (central differences over pixel_m).
// The arc tangent is atan_nonnegative: vectorizable, unlike std::atan.
Plane slope_degrees(const Plane& height, double pixel_m);
void slope_degrees(const Plane& height, double pixel_m, Plane& out);  // reusing `out`

// The arc tangent of x >= 0 without branches (Cephes' range reduction and rational
// approximation; within 2 ulp of std::atan, tested). NaN for NaN.
// Inlined everywhere (also into the AVX2 clones, where it vectorizes).
[[gnu::always_inline]] inline double atan_nonnegative(double x) {
  constexpr double kP[] = {-8.750608600031904122785E-1, -1.615753718733365076637E1,
                           -7.500855792314704667340E1, -1.228866684490136173410E2,
                           -6.485021904942025371773E1};
  constexpr double kQ[] = {2.485846490142306297962E1, 1.650270098316988542046E2,
                           4.328810604912902668951E2, 4.853903996359136964868E2,
                           1.945506571482613964425E2};
  constexpr double kTan3PiOver8 = 2.41421356237309504880, kMoreBits = 6.123233995736765886130E-17;
  // Every candidate computed, then selected: no branch.
  const bool big = x > kTan3PiOver8, middle = x > 0.66;
  const double inverse = -1 / x, shifted = (x - 1) / (x + 1);
  const double t = big ? inverse : middle ? shifted : x;
  const double base = big ? M_PI_2 : middle ? M_PI_4 : 0;
  const double more = big ? kMoreBits : middle ? 0.5 * kMoreBits : 0;
  const double z = t * t;
  const double p = (((kP[0] * z + kP[1]) * z + kP[2]) * z + kP[3]) * z + kP[4];
  const double q = ((((z + kQ[0]) * z + kQ[1]) * z + kQ[2]) * z + kQ[3]) * z + kQ[4];
  return base + (t * (z * p / q) + t + more);
}

// Positions (metres, on the sphere of the authalic radius) of the target pixels of `cell` and
// `ring` pixels around, computed on demand: exact on a lattice of every 8th global pixel (16th or
// 32nd for pixels of <= 9 m), bilinear in between, so neighbouring tiles compute the same values
// for the same pixel. Only the lattice is stored (the noise needs positions at its own lattice
// nodes, rarely at every pixel).
class PixelPositions {
 public:
  PixelPositions(const Grid& grid, CellId cell, int size, int refine, int ring);
  // Of target pixel (col, row), -ring <= col, row < M + ring.
  Vec3d at(int col, int row) const;
  // Of target pixels (col0 + k step, row), k < n, into out[k]: the same bits as at() (the same
  // formula per pixel), vectorized; the noise's lattice nodes along a node row.
  void along_row(int col0, int step, int n, int row, Vec3d* out) const;

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
