// Overview tiles: a cell's tile at half resolution, built from its four children's tiles.
#pragma once

#include <array>

#include "store/store.h"

namespace maquette {

// The overview tile of a cell from the tiles of its children, indexed by child digit
// (0 1 / 2 3; nullptr where a child has no tile). Each child fills one quadrant at half
// resolution: every 2x2 block of samples becomes one sample, per channel, the mean of its valid
// samples (continuous layers; rounded for integer dtypes) or their most frequent value, ties
// going to the smallest (categorical). Missing samples are NaN and, if the layer has one, the
// nodata value. A block without valid samples, and a quadrant without a child tile, get the
// fill value: nodata if set, else NaN for float dtypes and 0 for integer ones.
RawTile build_overview(const std::array<const RawTile*, 4>& children, const LayerInfo& layer);

}  // namespace maquette
