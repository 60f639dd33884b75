// A cell's guides laid in its face's chart (core/face_plane.h, FacePlane::chart_pixel) rather
// than as the store's halo folds them at the cube corners (core/halo.h), and found again by the
// face pixel they hold: synthesis.transfer lays its cells' land cover and altitude so, and the
// band along a polar face's turned edge (turned_edges.h) lays the equatorial face's chart from
// the polar cell's guides so.
//
// Contract: the tile with its halo is side = size + 2 * halo pixels a side (size a power of two,
// 0 <= halo <= size), row-major, its pixel (col, row) (from -halo) at index
// (row + halo) * side + col + halo, at pixel level L = cell.level() + log2(size). Face pixels
// are wrapped ones (0 <= col, row < 2^L). Pixels nobody holds (beyond one face width) are not
// found.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <unordered_map>
#include <vector>

#include "core/cell_id.h"
#include "core/face_plane.h"
#include "core/grid.h"

namespace maquette::synthesis {

// Where each face pixel lies among the pixels of `cell`'s tile with its halo, each halo pixel
// holding the face pixel `holds(col, row)` names (the tile's own pixels hold themselves).
// Precondition: `holds` names a pixel of the cell's own face only at its own place (as the
// store's halo and the face's chart do: beyond a face they reach only the neighbouring faces).
class HaloPixels {
 public:
  using Holds = std::function<std::optional<FaceCoord>(int col, int row)>;
  HaloPixels(CellId cell, int size, int halo, const Holds& holds);

  // The index of a pixel holding `pixel` (a wrapped face pixel at the tile's pixel level), or -1
  // when none does.
  int64_t find(const FaceCoord& pixel) const;

 private:
  struct Hash {
    size_t operator()(const FaceCoord& p) const;
  };
  struct Equal {
    bool operator()(const FaceCoord& a, const FaceCoord& b) const;
  };
  CellId cell_;
  int size_ = 0, halo_ = 0;
  // The other faces' pixels in the halo; the cell's own face's are found by their place.
  std::unordered_map<FaceCoord, int64_t, Hash, Equal> other_faces_;
};

// For each pixel of `cell`'s tile with its halo (tiles of `size`), the index of the pixel of the
// store's halo holding the face pixel the face's chart lays there; empty for a cell whose halo
// reaches no face corner (where the two are the same everywhere; they may be the same elsewhere
// too). Throws maquette::Error, naming the cell, when the chart lays a pixel the store's halo
// does not hold.
std::vector<int64_t> chart_order(const Grid& grid, const FacePlane& plane, CellId cell, int size,
                                 int halo);

}  // namespace maquette::synthesis
