#include "chart_guides.h"

#include <string>

#include "core/error.h"
#include "core/halo.h"
#include "core/tile.h"

namespace maquette::synthesis {
namespace {

uint64_t key(const FaceCoord& p) {
  return uint64_t(p.face) << 60 | uint64_t(p.col) << 30 | uint64_t(p.row);
}

}  // namespace

HaloPixels::HaloPixels(CellId cell, int size, int halo, const Holds& holds)
    : cell_(cell), size_(size), halo_(halo) {
  if (cell.level() + log2_tile_size(size) > 30)
    throw Error("synthesis: pixel level beyond 30 for " + cell.ToText());
  const int side = size + 2 * halo;
  for (int r = -halo; r < size + halo; ++r)
    for (int c = -halo; c < size + halo; ++c) {
      const std::optional<FaceCoord> p = holds(c, r);
      if (p && p->face != cell.face())
        other_faces_.emplace(key(*p), int64_t(r + halo) * side + c + halo);
    }
}

int64_t HaloPixels::find(const FaceCoord& pixel) const {
  if (pixel.face != cell_.face()) {
    const auto it = other_faces_.find(key(pixel));
    return it == other_faces_.end() ? -1 : it->second;
  }
  const int64_t c = pixel.col - int64_t(cell_.col()) * size_,
                r = pixel.row - int64_t(cell_.row()) * size_;
  if (c < -halo_ || c >= size_ + halo_ || r < -halo_ || r >= size_ + halo_) return -1;
  return (r + halo_) * (size_ + 2 * halo_) + c + halo_;
}

std::vector<int64_t> chart_order(const Grid& grid, const FacePlane& plane, CellId cell, int size,
                                 int halo) {
  const int level = cell.level() + log2_tile_size(size);
  const int64_t n = int64_t(1) << level, col0 = int64_t(cell.col()) * size,
                row0 = int64_t(cell.row()) * size;
  const auto beyond = [&](int64_t v) { return v < 0 || v >= n; };
  // Only a cell whose halo reaches beyond a face corner lays anything else.
  if (!(beyond(col0 - halo) || beyond(col0 + size + halo - 1)) ||
      !(beyond(row0 - halo) || beyond(row0 + size + halo - 1)))
    return {};
  const HaloPixels held(cell, size, halo,
                        [&](int c, int r) { return pixel_source(grid, cell, size, c, r); });
  const int side = size + 2 * halo;
  std::vector<int64_t> order(size_t(side) * size_t(side));
  for (int r = -halo; r < size + halo; ++r)
    for (int c = -halo; c < size + halo; ++c) {
      const int64_t i = int64_t(r + halo) * side + c + halo;
      const std::optional<FaceCoord> p =
          plane.chart_pixel(grid, cell.face(), level, col0 + c, row0 + r);
      order[size_t(i)] = p ? held.find(*p) : i;
      if (order[size_t(i)] < 0)
        throw Error("synthesis.transfer: " + cell.ToText() + "'s chart lays face " +
                    std::to_string(p->face) + " pixel (" + std::to_string(p->col) + ", " +
                    std::to_string(p->row) + ") beyond its halo of " + std::to_string(halo));
    }
  return order;
}

}  // namespace maquette::synthesis
