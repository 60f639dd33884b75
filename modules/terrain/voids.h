// Voids of a DEM tile: the 4-connected components of NaN samples that reach the tile's interior,
// found in the whole window (tile + halo) so that a void crossing the tile border is seen whole.
#pragma once

#include <vector>

#include "core/tile.h"

namespace maquette::terrain {

struct Void {
  // Window sample indices (row-major over the tile with its halo, see Tile::data), ascending, so
  // the order of a void's samples does not depend on where the window starts.
  std::vector<int> samples;
  int extent = 0;             // larger side of the bounding box, in pixels
  bool reaches_edge = false;  // touches the window's edge, so it may continue beyond it
};

// The voids of `dem` (one channel) with at least one sample inside the tile, in the order of
// their first interior sample (row-major).
std::vector<Void> find_voids(const Tile<float>& dem);

}  // namespace maquette::terrain
