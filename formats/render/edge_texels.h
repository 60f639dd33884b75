// Imagery carried a bounded distance past its edge: terrain the imagery has no texel for (a DEM
// reaching past the scene's footprint, no tile or no-data texels) takes the colour of the nearest
// texel with data, clamp-to-edge within a reach. On the texel lattice of the imagery's level (in
// the grid's plane: every cell's square is `tile_size` texels a side), each texel without data
// takes the value of the nearest texel with data whose centre is at most `reach` texels from its
// own (Euclidean, in texels; ties: the first in a fixed order of rings), none beyond; a point is
// read bilinearly from the four texel centres around it, the weights renormalized over those that
// have a value. Texels with data keep their own value. Texel centres off the six squares of the
// plane are taken as without data. Cost: a texel without data looks among the ~3.14 reach^2
// texels within the reach, unless no cell within the reach has a tile (then at once): a large
// area of no-data texels inside tiles would be slow. Values depend on the point alone (not on the
// calls before): the same bits for any thread count. One object per thread (it caches tiles and
// the texels it has resolved).
#pragma once

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "core/grid.h"
#include "image/layer_sampler.h"
#include "store/store.h"

namespace maquette {

class EdgeTexels {
 public:
  // `texture`: uint8 imagery of 1, 3 or 4 channels, read at its own level; reach >= 1 texels.
  EdgeTexels(const Store& store, const Grid& grid, const LayerInfo& texture, int reach);

  // Writes the 3 bands (a single channel repeated) at `q`, a point of the grid's plane; false,
  // writing nothing, when none of the four texel centres around q has a value within the reach.
  bool sample(PlanePoint q, float* out);

 private:
  using Texel = std::array<float, 3>;  // NaN: no data within the reach
  struct Key {                         // a texel (or a cell) of the lattice: x right, y up
    int64_t x, y;
    bool operator==(const Key&) const = default;
  };
  struct KeyHash {
    size_t operator()(const Key& k) const {
      return std::hash<int64_t>()(k.x) ^ (std::hash<int64_t>()(k.y) * 0x9e3779b97f4a7c15ull);
    }
  };
  const Texel& resolved(Key k);  // the lattice texel k's own value or its nearest's
  // The imagery's texel k (NaN where no data); false where its cell has no tile or k is off the
  // plane.
  bool read(Key k, Texel& out);
  bool data(Key k, Texel& out);  // read, and with data
  bool tiles_near(Key k);        // whether a cell within the reach of texel k has a tile

  LayerSampler sampler_;  // nearest: a texel's own value at its centre
  int channels_, reach_, tile_size_;
  double texel_;  // metres of the plane per texel
  std::vector<PlaneSquare> faces_;
  std::unordered_map<Key, Texel, KeyHash> resolved_;
  std::unordered_map<Key, bool, KeyHash> tiles_near_;  // by cell (texels / tile_size)
};

}  // namespace maquette
