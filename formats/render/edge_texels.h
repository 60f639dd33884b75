// Imagery carried a bounded distance past its edge: terrain the imagery has no texel for (a DEM
// reaching past the scene's footprint, no tile or no-data texels) takes the colour of the nearest
// texel with data, clamp-to-edge within a reach. On the texel lattice of the imagery's level (in
// the grid's plane: every cell's square is `tile_size` texels a side), each texel without data
// takes the value of the nearest texel with data whose centre is at most `reach` texels from its
// own (Euclidean, in texels; ties: the first in a fixed order of rings: the Chebyshev radius r,
// then in ring r its rows dy = -r and r, x ascending, each column's two in that order, then its
// columns dx = -r and r, y ascending, likewise), none beyond; a point is read bilinearly from the
// four texel centres around it, the weights renormalized over those that have a value. Texels with
// data keep their own value. Texel centres off the six squares of the plane are taken as without
// data. Cost: the lattice is resolved a block of B = max(64, 2 reach) texels a side at a time, on
// the first point that needs one of its texels: nothing when no cell within the reach of the block
// has a tile, else the block and its reach read once ((B + 2 reach)^2 <= 4 B^2 texels), each
// column's nearest texel with data above and below each row found by one scan, and each texel
// without data takes the least of the 2 (2 reach + 1) candidates those give (the nearest texel
// with data in each column within the reach is one of them): O(reach) a texel whatever the
// no-data areas inside tiles. Values depend on the point alone (not on the calls before): the
// same bits for any thread count. One object per thread (it caches tiles and resolved blocks).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include "core/grid.h"
#include "image/layer_sampler.h"
#include "store/store.h"

namespace maquette {

class EdgeTexels {
 public:
  // `texture`: uint8 imagery of 1, 3 or 4 channels, read at its own level from `tiles`
  // (LayerSampler::shared_tiles of it at that level, which may be shared with other samplers and
  // other threads' EdgeTexels); reach >= 1 texels. Throws maquette::Error naming both layers and
  // levels when the tiles are another layer's or level's.
  EdgeTexels(std::shared_ptr<LayerSampler::Tiles> tiles, const Grid& grid, const LayerInfo& texture,
             int reach);

  // Writes the 3 bands (a single channel repeated) at `q`, a point of the grid's plane; false,
  // writing nothing, when none of the four texel centres around q has a value within the reach.
  bool sample(PlanePoint q, float* out);

  // Drops the resolved blocks (resolved again when asked: the same values), so that memory stays
  // bounded over a picture's strips; the tiles are dropped by their owner
  // (LayerSampler::forget_unused(Tiles&)).
  void forget_unused();

 private:
  using Texel = std::array<float, 3>;  // NaN: no data within the reach
  struct Key {                         // a texel, a block or a cell of the lattice: x right, y up
    int64_t x, y;
    bool operator==(const Key&) const = default;
  };
  struct KeyHash {
    size_t operator()(const Key& k) const {
      return std::hash<int64_t>()(k.x) ^ (std::hash<int64_t>()(k.y) * 0x9e3779b97f4a7c15ull);
    }
  };
  // A block's texels, row by row: each its own value or its nearest's; empty when no cell within
  // the reach of the block has a tile (all without a value).
  using Block = std::vector<Texel>;
  const Texel& resolved(Key k);  // the lattice texel k's own value or its nearest's
  Block resolve_block(Key b);
  // The imagery's texel k (NaN where no data); false where its cell has no tile or k is off the
  // plane.
  bool read(Key k, Texel& out);
  bool tiles_near(Key b);  // whether a cell within the reach of block b's texels has a tile

  LayerSampler sampler_;  // nearest: a texel's own value at its centre
  int channels_, reach_, tile_size_, block_;
  double texel_;  // metres of the plane per texel
  std::vector<PlaneSquare> faces_;
  std::unordered_map<Key, Block, KeyHash> blocks_;
  std::unordered_map<Key, bool, KeyHash> has_tile_;  // by cell (texels / tile_size)
};

}  // namespace maquette
