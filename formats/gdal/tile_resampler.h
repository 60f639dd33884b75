// One thread's tile maker: the samples of a cell's tile from the sources, mosaicked in order
// (a later source fills only samples, per channel, that earlier ones left missing).
#pragma once

#include <memory>
#include <vector>

#include "core/grid.h"
#include "core/tile.h"
#include "gdal/pixel_map.h"
#include "gdal/raster_source.h"
#include "gdal/resample.h"

namespace maquette {

class TileResampler {
 public:
  // Source windows larger than this (window pixels per side) are read at a coarser step.
  static constexpr int kMaxWindow = 2048;

  TileResampler(const Grid& grid, const std::vector<RasterSource>& sources, Resampling resampling,
                bool categorical);
  ~TileResampler();

  // Fills `tile` (size x size x channels, NaN where no source has data; its storage is reused
  // when the shape matches); returns whether any sample is valid.
  bool make(CellId cell, int size, Tile<float>& tile);

 private:
  struct Source;
  // `fresh`: no source has filled any sample of the tile yet (every sample is missing).
  void sample(Source& s, CellId cell, Tile<float>& tile, bool fresh);
  std::vector<std::unique_ptr<Source>> sources_;
  Resampling resampling_;
  bool categorical_;
  PixelMap map_;
  Window window_;
};

}  // namespace maquette
