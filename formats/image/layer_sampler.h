// A layer's tiles at one level sampled at points of the globe: the tile of the cell holding a
// point, padded with a one-pixel halo from its neighbours (across faces too, core/halo.h), is
// read bilinearly, nearest, or as classes with smoothed boundaries, so sampling never stops at a
// tile edge or a face seam. Shared by the quicklooks, the GeoTIFF exports to other CRSs and the
// panorama's texture and guides.
#pragma once

#include <memory>

#include "core/grid.h"
#include "core/tile.h"
#include "store/store.h"

namespace maquette {

class LayerSampler {
 public:
  // How a point between samples is read (each channel on its own).
  enum class Read {
    kNearest,
    // The four samples around, weighted bilinearly (missing ones left out).
    kBilinear,
    // A categorical layer's class with its boundaries smoothed: of the 3 x 3 samples around the
    // nearest, the value whose samples weigh most under a quadratic B-spline (weights (1/2 - t)^2
    // / 2, 3/4 - t^2, (1/2 + t)^2 / 2 along each axis, t the point's offset from the nearest
    // sample, in samples; ties, in practice at points half way between samples, to the nearest
    // sample's value, then to the value met first in row order). A class's area is then bounded by
    // a smooth curve through its cells' staircase instead of the staircase, on the staircase's mean
    // line: the generalization a painter's line makes of 30 m land-cover cells
    // (tests/render/smooth_labels_test.cpp: turns of at most ~5 degrees a twentieth of a cell where
    // the staircase turns by right angles; up to 0.44 cell from a straight boundary's line, the
    // staircase 0.68). Every value read is one of the 3 x 3 samples (missing samples count as one
    // value: NaN); a lone cell in another class shrinks to a rounded blob within it.
    kSmoothLabels,
  };

  // A layer's tiles at one level and their halos, each read and assembled once for all the
  // samplers that share them (one a thread: safe to share between threads).
  class Tiles;
  static std::shared_ptr<Tiles> shared_tiles(const Store& store, const Grid& grid,
                                             const LayerInfo& layer, int level);
  // Drops the tiles and halos of `tiles` not used since the last call (by any of its samplers):
  // called while none of them samples. Each sampler of them starts a run after it (start_run).
  static void forget_unused(Tiles& tiles);
  // `cell`'s tile in `tiles` (of the layer's level, or a coarser level's overview tile), read and
  // decoded by the first that asks; null when the store has none. Valid until forget_unused(tiles)
  // drops it: for callers assembling their own halos (render/terrain_scene.h's two rings).
  static const Tile<float>* tile(Tiles& tiles, CellId cell);

  // Reads `layer`'s tiles at `level` (the layer's level, or a coarser one's overview tiles).
  LayerSampler(const Store& store, const Grid& grid, const LayerInfo& layer, int level, Read read);
  // Reads them from `tiles` (shared_tiles), shared with other samplers: the same values.
  LayerSampler(std::shared_ptr<Tiles> tiles, Read read);

  // Writes the layer's channels at `p` to out[0 .. channels - 1]; `cell` is the cell at the
  // sampler's level holding `p` (Grid::cells_from_points). Bilinear sampling leaves out missing
  // samples (weights renormalized), and a point whose nearest sample is missing gets NaN;
  // kSmoothLabels counts missing samples as one more value (NaN may win, or lose). Returns
  // false, writing nothing, when the cell has no tile. The previous call's cell, when `cell` is
  // it again, is not looked up.
  bool sample(LonLat p, CellId cell, float* out);
  // The same at `q`, a point of the grid's plane (Grid::forward), for callers that have it
  // without the projection: while q stays in the previous call's cell (its square, edges included:
  // the halo covers them) that cell's tile is read again, else the cell holding q is looked up.
  bool sample(PlanePoint q, float* out);
  // The next plane point's cell looked up afresh. A point on the edge of two squares is read from
  // the previous call's cell when that is one of them, and the two tiles' reads may differ (in the
  // last bit bilinearly; by a class with kNearest or kSmoothLabels, whose nearest sample is then a
  // tie): callers whose points come in runs (a picture's rows) call this at the
  // start of each run, so that a value depends on its run alone, never on which runs a thread
  // sampled before (the same bits for any thread count).
  void start_run() { last_ = last_cell_ = nullptr; }

  // The layer and the level of the tiles it reads.
  const LayerInfo& layer() const { return layer_; }
  int level() const;

  // Drops the tiles not used since the last call: keeps memory bounded when points sweep across
  // a large region. Not for a sampler of shared tiles (forget_unused(Tiles&)).
  void forget_unused();

 private:
  struct Halo;
  void read(const Halo& h, PlanePoint q, float* out) const;

  std::shared_ptr<Tiles> tiles_;
  const LayerInfo& layer_;
  Read read_;
  const Halo* last_ = nullptr;       // the cell of the last plane point sampled
  const Halo* last_cell_ = nullptr;  // the last cell sampled at a lon/lat
};

}  // namespace maquette
