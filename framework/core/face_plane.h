// A grid's six faces laid in one plane, none turned: the equatorial faces side by side in a row
// (each unturned beside its neighbours, the row closing on itself), one polar face above the
// equatorial face it meets unturned and the other below the one it meets unturned. In rHEALPix's
// default layout: O P Q R left to right (O's left edge the antimeridian), N above O and S below O.
// The places are read off the grid's own adjacency (Grid::wrap, through UnfoldedFaces), never
// assumed.
//
// A face pixel (col, row) at a level of n = 2^level pixels a face is plane pixel
// (face_col * n + col, face_row * n + row), (face_col, face_row) its face's place in face widths.
// The plane is continuous (a pixel's neighbours in the plane are its neighbours on the globe)
// across every edge between two equatorial faces, across the antimeridian when plane columns are
// taken modulo wrap_columns() (the row's width), and across the two edges where a polar face
// meets the equatorial face it is laid against. Not across the polar faces' other three edges each:
// there the neighbour is turned by 90 or 180 degrees (and three faces meet at each cube corner),
// which no single planar chart can lay unturned.
//
// A face's chart (chart_pixel): the face pixel a cell of that face reads at a pixel of its frame
// continued beyond the face, as the store's halo reads it (Grid::wrap, core/halo.h) except in the
// quadrant diagonally beyond a face corner, where three faces meet and the halo folds: there an
// equatorial face, and a polar face toward the row, read the plane continued (the equatorial face
// at that plane column, then across its edge beyond the row if the pixel lies beyond it). So the
// cells of the equatorial faces read one pixel at each plane position their charts share, up to
// the cube corners, and so do a polar face and the equatorial face it is laid against, but beyond
// the polar face's turned edges: there the polar face's chart lays the neighbour as the polar
// face meets it, the equatorial faces' the polar face as they meet it.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "core/cell_id.h"
#include "core/grid.h"

namespace maquette {

class FacePlane {
 public:
  // Throws maquette::Error when the grid's faces cannot be laid so: no row of equatorial faces
  // unturned side by side, or a face left with no place.
  explicit FacePlane(const Grid& grid);

  // The face's place in the plane, in face widths (column, row).
  const std::array<int64_t, 2>& place(int face) const { return places_[size_t(face)]; }
  // The faces of the equatorial row: plane columns repeat every ring_faces() face widths.
  int ring_faces() const { return ring_faces_; }

  // The plane pixel of pixel (col, row) of `cell`'s tile of `size` pixels a side (at pixel level
  // cell.level() + log2(size); col and row may lie beyond the tile, in its face's frame).
  std::array<int64_t, 2> tile_pixel(CellId cell, int size, int64_t col, int64_t row) const;
  // The period of the plane's columns at that pixel level: ring_faces() face widths.
  int64_t wrap_columns(CellId cell, int size) const;

  // The face pixel `face`'s chart lays at pixel (col, row) of its frame at pixel level `level`
  // (above); nullopt more than one face width beyond the face, as Grid::wrap. Preconditions:
  // 0 <= face < CellId::kNumFaces, 0 <= level <= 60.
  std::optional<FaceCoord> chart_pixel(const Grid& grid, int face, int level, int64_t col,
                                       int64_t row) const;

 private:
  std::array<std::array<int64_t, 2>, CellId::kNumFaces> places_{};
  std::array<int, CellId::kNumFaces> ring_order_{};  // the row's faces by column
  int ring_faces_ = 0;
};

}  // namespace maquette
