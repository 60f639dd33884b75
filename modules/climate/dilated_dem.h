// A DEM tile (halo included) and its running maxima along rows and along columns over centred
// runs of 2^l + 1 pixels, l = 1..levels: the far samples of a horizon march, spaced 2^l pixels
// apart along its longer axis, read level l along that axis, so that no peak between two
// samples is passed over (a sample's run reaches the next one's).
// Samples without data are left out of a maximum; a square without any data is NaN.
#pragma once

#include <array>
#include <vector>

#include "core/tile.h"

namespace maquette::climate {

enum class Axis { Col, Row };  // along a row (+col) or along a column (+row)

class DilatedDem {
 public:
  DilatedDem(const Tile<float>& dem, int levels);

  int levels() const { return int(maxima_[0].size()); }
  // Level 0 is the DEM itself.
  const Tile<float>& level(int l, Axis axis) const {
    return l == 0 ? dem_ : maxima_[int(axis)][size_t(l - 1)];
  }

 private:
  const Tile<float>& dem_;
  std::array<std::vector<Tile<float>>, 2> maxima_;
};

}  // namespace maquette::climate
