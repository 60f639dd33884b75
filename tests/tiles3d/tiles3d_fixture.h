// A small store for the 3D Tiles tests: `dem` (float32 metres, a smooth field of lon/lat) and
// `rgb` (uint8 imagery) on a 2 x 2 block of level-6 cells and on two cells either side of the
// P/Q face seam, 32 x 32 samples per tile, overviews built; 3D content layers `boxes` (a 100 m
// box on the terrain at the centre of block[0]) and `trees` (kTreeCount cones on block[1],
// instance i: 0.01 degrees east and south of the centre per i, scale 20 + i m, heading 30 i).
#pragma once

#include <string>
#include <vector>

#include "core/grid.h"

namespace maquette::test {

inline constexpr int kTileSize = 32;
inline constexpr int kLevel = 6;
inline constexpr int kTreeCount = 5;

struct Tiles3dFixture {
  std::string store_path;
  std::vector<CellId> block;  // 2 x 2, one parent
  std::vector<CellId> seam;   // on face P, then on face Q, sharing an edge
};
const Tiles3dFixture& tiles3d_fixture();

// A store holding only `dem` (the same field, float32, no nodata) on `cells` (one level).
std::string corner_store(const std::vector<CellId>& cells);

double dem_field(LonLat p);  // metres

}  // namespace maquette::test
