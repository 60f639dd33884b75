// Voids of any size filled through the DEM's overview pyramid: a cascadic multigrid solve of the
// Laplace equation (membrane) from the coarsest level that holds data around the void down to
// the tile's own, each level started from the bilinear upsampling of the coarser level's fill
// and smoothed by Jacobi sweeps with the known samples of that level held fixed (see README.md).
// Every value is a function of global pixel positions and of a bounded neighbourhood at each
// level, so tiles fill shared voids with the same bits.
#pragma once

#include <functional>

#include "core/cell_id.h"
#include "core/tile.h"

namespace maquette::terrain {

// Jacobi sweeps per level: the finest level reads the input's halo this far plus one.
inline constexpr int kPyramidSweeps = 24;
// Halo of the coarse levels' tiles: their windows reach at most this far beyond the tile.
inline constexpr int kPyramidHalo = 64;
// Pixel level of the coarsest level (256 pixels along a face, ~39 km), whatever the tile size: a
// pyramid tile finer than that climbs to the cell's face and then halves the face's tile.
inline constexpr int kCoarsestPixelLevel = 8;

// The tile of level `levels_up` of the pyramid around a cell of tile size `size`: its ancestor
// that many levels up, or, above its face, the face with its tile halved (levels_up - cell level)
// times (size >> that).
struct PyramidTile {
  CellId cell;
  int size = 0;
};
PyramidTile pyramid_tile(CellId cell, int size, int levels_up);

// Level `levels_up` (>= 1) of the pyramid around a cell: the tile of pyramid_tile (the overview
// of the ancestor, the face's overview halved above the face), with a halo of `halo` pixels
// (nodata as NaN; core/halo.h's assembly).
using PyramidFetch = std::function<Tile<float>(int levels_up, int halo)>;
// Whether pixel (col, row) of the tile of level `levels_up` (pyramid_tile; 0: the cell's own;
// halo pixels included) lies inside the footprint of the input's sources (core/data_footprint.h).
using FootprintTest = std::function<bool(int levels_up, int col, int row)>;

// The tile of `cell` (its samples, no halo) with NaN samples filled. With a footprint test
// (`inside` not empty), every NaN sample inside the footprint: samples outside it take no part
// (the membrane's border there is free: no flux across the edge of the data). Without one, the
// NaN samples that the pyramid encloses: one whose pixel at some coarser level has data within
// 16 pixels in each of the four axis directions (so voids of any size inside the data are
// filled, and nothing is extrapolated beyond the edge of convex data). `dem` is the cell's tile
// with a halo of at least kPyramidSweeps + 1 pixels. Samples that are not NaN are copied; NaN
// samples not filled stay NaN.
Tile<float> fill_through_pyramid(const Tile<float>& dem, CellId cell, const PyramidFetch& fetch,
                                 const FootprintTest& inside);

}  // namespace maquette::terrain
