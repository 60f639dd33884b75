#include "core/tile_frame.h"

#include "core/halo.h"
#include "core/tile.h"

namespace maquette {
namespace {

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

}  // namespace

TileFrame::TileFrame(const Grid& grid, CellId cell, int size)
    : size_(size), pixels_(size_t(size + 2) * size_t(size + 2)) {
  const int pixel_level = cell.level() + log2_tile_size(size);
  for (int row = -1; row <= size; ++row)
    for (int col = -1; col <= size; ++col) {
      const std::optional<FaceCoord> source = pixel_source(grid, cell, size, col, row);
      if (!source) continue;
      const LonLat p = pixel_centre(grid, *source, pixel_level);
      pixels_[size_t(row + 1) * size_t(size + 2) + size_t(col + 1)] = {
          p, maquette::ecef(p), east_unit(p), north_unit(p), true};
    }
}

EastNorth TileFrame::tangent(int col, int row, const Vec3& d) const {
  const Pixel& p = pixel(col, row);
  return {dot(d, p.east), dot(d, p.north)};
}

}  // namespace maquette
