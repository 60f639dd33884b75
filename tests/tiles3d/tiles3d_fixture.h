// A small store for the 3D Tiles tests: `dem` (float32 metres, a smooth field of lon/lat) and
// `rgb` (uint8 imagery) on a 2 x 2 block of level-6 cells and on two cells either side of the
// P/Q face seam, 32 x 32 samples per tile, overviews built.
#pragma once

#include <string>
#include <vector>

#include "core/grid.h"

namespace maquette::test {

inline constexpr int kTileSize = 32;
inline constexpr int kLevel = 6;

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
