// The inputs of the procedural model at the target resolution of one tile: the DEM (and any
// climate raster) upsampled by a uniform cubic B-spline (paper 4: bilinear gives piecewise
// linear patches), slope from the upsampled heights, and every pixel's position on the globe
// for the noise. A target tile is `refine` levels finer than the input tiles: M = size << refine
// pixels a side. Planes carry a ring of pixels beyond the tile so that slopes and normals at its
// border come from the same values its neighbours compute (no seams).
#pragma once

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

// Slope in degrees, with one ring less than `height` (central differences over pixel_m).
Plane slope_degrees(const Plane& height, double pixel_m);

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

 private:
  int shift_ = 3;              // node spacing 2^shift pixels
  int64_t gc0_ = 0, gr0_ = 0;  // global face pixel of target pixel (0, 0)
  int64_t nc0_ = 0, nr0_ = 0;  // global node coordinates of node[0]
  int nodes_ = 0;              // a side
  std::vector<Vec3d> node_;
};

}  // namespace maquette::texture
