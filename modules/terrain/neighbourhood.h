// The 3x3 neighbourhood of a pixel in true metres: its 8 neighbours' offsets in the pixel's
// east/north tangent plane, from the tile's true geometry (core/tile_frame.h), for the local
// surface fits of terrain.derive (surface_fit.h).
#pragma once

#include <array>

#include "core/tile_frame.h"

namespace maquette::terrain {

// East-north offsets (metres, in the centre pixel's tangent plane) of a 3x3 neighbourhood,
// row-major from the top-left; index 4 is the centre (0, 0).
struct Neighbourhood {
  std::array<double, 9> east{}, north{};
};

// Neighbourhood of interior pixel (col, row); false when a neighbour has no position.
bool neighbourhood(const TileFrame& frame, int col, int row, Neighbourhood& out);

}  // namespace maquette::terrain
