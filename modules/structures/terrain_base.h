// The height a building stands on: the lowest terrain under its footprint.
#pragma once

#include <optional>
#include <vector>

#include "core/grid.h"
#include "core/tile.h"
#include "footprint.h"

namespace maquette::structures {

// Rings in the DEM tile's pixel coordinates: (col, row) continuous, pixel (c, r) covering
// [c, c + 1) x [r, r + 1), row down; outer ring first; open or closed, either orientation.
using PixelRing = std::vector<PlanePoint2>;

// Those pixel coordinates of a point in the tile of `tile_size` pixels of `cell`.
struct PixelFrame {
  PlaneSquare square;
  double pixels_per_metre;
  PixelFrame(const Grid& grid, CellId cell, int tile_size)
      : square(grid.plane_square(cell)), pixels_per_metre(tile_size / square.side) {}
  PlanePoint2 operator()(const Grid& grid, LonLat p) const {
    const PlanePoint q = grid.forward(p);
    return {(q.x - square.x_min) * pixels_per_metre, (square.y_max - q.y) * pixels_per_metre};
  }
};

// The lowest DEM sample among the pixels the footprint touches and their 8 neighbours. Touched:
// the pixels whose centre lies inside the footprint and those its rings pass through (sampled
// every quarter pixel; a pixel only grazed is a neighbour of one sampled). The neighbours are
// there because the exported terrain's vertices are the means of the 4 pixels around each pixel
// corner (formats/gltf/terrain_mesh.h): so the terrain mesh is nowhere below the result under
// the footprint (nothing floats), and the base is the lowest of the samples the footprint stands
// on (no deeper). NaN samples (no data) are skipped; nullopt when all are NaN.
// Throws InvalidFootprint when the pixels needed leave the tile and its halo, naming by how much.
std::optional<float> lowest_terrain(const Tile<float>& dem, const std::vector<PixelRing>& rings);

}  // namespace maquette::structures
