// texture.classify's exclusion by a features layer: the pixels of a tile, and of a ring around it,
// whose centre lies inside a polygon of the layer. Only the features indexed in the cells those
// pixels lie in are read, so the answer for a pixel does not depend on the tile computing it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/grid.h"
#include "store/store.h"

namespace maquette::texture {

// (size + 2 ring)^2 flags, row-major from pixel (-ring, -ring) of `cell`'s tile; 1: inside.
// Throws maquette::Error prefixed with `where` (the parameter) naming the layer when it is
// absent, not a features layer or empty, and the feature when it is not a (multi)polygon.
std::vector<uint8_t> features_mask(const Store& store, const std::string& layer,
                                   const std::string& where, const Grid& grid, CellId cell,
                                   int size, int ring);

}  // namespace maquette::texture
