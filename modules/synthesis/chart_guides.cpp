#include "chart_guides.h"

#include <cassert>
#include <string>

#include "core/error.h"
#include "core/halo.h"
#include "core/splitmix64.h"
#include "core/tile.h"

namespace maquette::synthesis {

size_t HaloPixels::Hash::operator()(const FaceCoord& p) const {
  return size_t(
      splitmix64_mix(uint64_t(p.col) ^ splitmix64_mix(uint64_t(p.row) ^ uint64_t(p.face) << 61)));
}

bool HaloPixels::Equal::operator()(const FaceCoord& a, const FaceCoord& b) const {
  return a.face == b.face && a.col == b.col && a.row == b.row;
}

HaloPixels::HaloPixels(CellId cell, int size, int halo, const Holds& holds)
    : cell_(cell), size_(size), halo_(halo) {
  const int side = size + 2 * halo;
  for (int r = -halo; r < size + halo; ++r)
    for (int c = -halo; c < size + halo; ++c) {
      if (c >= 0 && c < size && r >= 0 && r < size) continue;  // the tile: its own pixels
      const std::optional<FaceCoord> p = holds(c, r);
      if (!p) continue;
      const int64_t i = int64_t(r + halo) * side + c + halo;
      if (p->face != cell.face())
        other_faces_.emplace(*p, i);
      else
        assert(find(*p) == i);  // an own-face pixel at its own place (the precondition)
    }
}

int64_t HaloPixels::find(const FaceCoord& pixel) const {
  assert(pixel.col >= 0 && pixel.row >= 0);  // wrapped
  if (pixel.face != cell_.face()) {
    const auto it = other_faces_.find(pixel);
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
