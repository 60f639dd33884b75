#include "test_tiles.h"

namespace maquette::test {

std::vector<TileSample> tile_samples(const Grid& grid, CellId cell, int size) {
  const PlaneSquare sq = grid.plane_square(cell);
  const double pixel = sq.side / size;
  std::vector<TileSample> samples;
  samples.reserve(size_t(size) * size_t(size));
  for (int r = 0; r < size; ++r)
    for (int c = 0; c < size; ++c) {
      const PlanePoint p{sq.x_min + (c + 0.5) * pixel, sq.y_max - (r + 0.5) * pixel};
      samples.push_back({p, grid.inverse(p), global_col(cell, size, c), global_row(cell, size, r)});
    }
  return samples;
}

std::vector<CellId> block_of_four(const Grid& grid, LonLat p, int level) {
  const CellId parent = grid.cell_from_point(p, level - 1);
  return {parent.child(0), parent.child(1), parent.child(2), parent.child(3)};
}

LayerInfo layer_info(const std::string& name, DType dtype, int channels, int tile_size, int level) {
  LayerInfo info;
  info.name = name;
  info.dtype = dtype;
  info.channels = channels;
  info.tile_size = tile_size;
  info.level = level;
  return info;
}

}  // namespace maquette::test
