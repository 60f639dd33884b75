// Where the samples of a tile fall in a source: source pixel coordinates of the N x N sample
// centres of a cell's tile (the centres of its descendants at level L + log2 N).
#pragma once

#include <vector>

#include "core/grid.h"
#include "gdal/source_transform.h"

namespace maquette {

struct PixelMap {
  int size = 0;
  std::vector<double> x, y;  // row-major, NaN where the transform fails
};

// Like GDAL's approximate transformer: the exact transform (grid inverse, then PROJ) runs on a
// lattice every `kStep` samples; inside each lattice block the coordinates are interpolated
// bilinearly when the interpolation error at the block's centre is below 1/8 source pixel and the
// lattice bends little enough at the ends of the block's edges that the edges are within 1/8
// pixel too (a kink such as a polar face's diagonal, where rows of samples turn by ~50 degrees on
// the ground, can cut a block's corner and leave its centre right), and transformed exactly
// otherwise (near the poles, seams, antimeridian, projection edges, polar faces' diagonals).
// pixel_map_test checks every sample within 1/8 source pixel on tiles across the diagonals.
class PixelMapper {
 public:
  static constexpr int kStep = 16;
  static constexpr double kMaxError = 0.125;  // source pixels

  PixelMapper(const Grid& grid, const RasterSource& source) : grid_(grid), transform_(source) {}

  void map(CellId cell, int size, PixelMap& out);

 private:
  // Exact source pixel coordinates of tile samples (col, row) given as doubles.
  void exact(CellId cell, int size, std::vector<double>& col_x, std::vector<double>& row_y);
  const Grid& grid_;
  SourceTransform transform_;
};

}  // namespace maquette
