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
// Pixel level of the coarsest level (256 pixels along a face, ~39 km): the tile of a face for
// the default tile size, so that tilings of up to 256-pixel tiles climb to the same level (larger
// tiles stop at their faces' tiles: pixel level log2(tile size)).
inline constexpr int kCoarsestPixelLevel = 8;

// Level `levels_up` (>= 1) of the pyramid around a cell: the overview tile of its ancestor that
// many levels up, with a halo of `halo` pixels (nodata as NaN; core/halo.h's assembly).
using PyramidFetch = std::function<Tile<float>(int levels_up, int halo)>;

// The tile of `cell` (its samples, no halo) with every NaN sample that the pyramid encloses
// filled: one whose pixel at some coarser level has data within 16 pixels in each of the four
// axis directions (so voids of any size inside the data are filled, and nothing is extrapolated
// beyond the edge of convex data). `dem` is the cell's tile with a halo of at least kPyramidSweeps
// + 1 pixels. Samples that are not NaN are copied; NaN samples not enclosed stay NaN.
Tile<float> fill_through_pyramid(const Tile<float>& dem, CellId cell, const PyramidFetch& fetch);

}  // namespace maquette::terrain
