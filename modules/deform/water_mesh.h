// The closed triangle mesh of a lake (water_body.h) on its raster: the water's top surface at
// the level, triangulated from the shoreline (its vertices are the shoreline's corners only: one
// strip per wet run of a row, between the run's two corner lines, zipped from the shoreline
// corners on each line; no vertex inside the lake, no degenerate triangle), walls down from the
// shoreline, one quad per dry pixel side, and a flat bottom: the top's triangulation (facing down)
// at lake_flat_bottom, below the lowest bed. The prism of the lake's outline, what a viewer draws
// (the bottom lies under the terrain, never seen), with no vertex inside the lake; its volume is
// not the water's (the fog volume is made from the depths: water_columns.h).
// Vertices are in pixel-corner coordinates (col, row: the raster's corner lattice, row down).
// Time and memory are linear in the lake's pixels (and its bounding box's corners). Built by
// blocks of 64 pixel rows in parallel: the triangles block by block (in each, the top strips of
// its rows with the bottom's, then each wet pixel's walls), the vertices
// numbered block by block in the order of first use, a corner shared with the rows above
// belonging to the block above; the blocks fixed from the lake's first row, so the same mesh for
// any thread count. The first vertex is the first top strip's first corner, on the shore.
//
// Contract: a non-empty body of `basin` (fill_basin). The mesh is closed and consistently
// oriented: each edge is in exactly two triangles, once in each direction; triangles are
// counter-clockwise seen from outside in the right-handed frame (col, -row, height).
#pragma once

#include <cstdint>
#include <vector>

#include "water_body.h"

namespace maquette::deform {

struct LakeVertex {
  double col = 0, row = 0;  // pixel-corner lattice: pixel (c, r) spans [c, c + 1] x [r, r + 1]
  double height = 0;        // metres
};

struct LakeMesh {
  std::vector<LakeVertex> vertices;
  std::vector<uint32_t> indices;  // triangles
};

// The flat bottom's height: 1 m below the lowest terrain of the lake's pixels.
double lake_flat_bottom(const BasinRaster& basin, const WaterBody& body);

// The mesh with its flat bottom at `bottom` (lake_flat_bottom, below the lake's bed); of `basin`
// only its width and height are read (the caller may build the mesh after the raster is gone).
LakeMesh lake_mesh(const BasinRaster& basin, const WaterBody& body, double bottom);

}  // namespace maquette::deform
