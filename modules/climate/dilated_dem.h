// A DEM tile (halo included) and its maxima over centred squares of 2^l + 1 pixels a side,
// l = 1..levels, read by the far samples of a horizon march. Samples at level l lie 2^l pixels
// apart along the march's longer axis, and between two of them the march moves at most as far
// along the shorter one: the squares of neighbouring samples each reach halfway along both axes,
// so no peak on the path is passed over, however oblique the march.
// Samples without data are left out of a maximum; a square without any data is NaN.
#pragma once

#include <vector>

#include "core/tile.h"

namespace maquette::climate {

class DilatedDem {
 public:
  DilatedDem(const Tile<float>& dem, int levels);

  int levels() const { return int(maxima_.size()); }
  // Level 0 is the DEM itself.
  const Tile<float>& level(int l) const { return l == 0 ? dem_ : maxima_[size_t(l - 1)]; }

 private:
  const Tile<float>& dem_;
  std::vector<Tile<float>> maxima_;
};

}  // namespace maquette::climate
