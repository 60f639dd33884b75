// A grid's faces unfolded into one plane around an anchor face: the anchor's face pixel frame at
// some level (col, row counted from its top-left corner) extended beyond its four edges, each face
// across an edge laid there as it meets the anchor, turned by a multiple of 90 degrees. The turn
// and offset of each neighbour are derived from Grid::wrap (so from the grid's own adjacency),
// never assumed. In rHEALPix's default layout N sits above O unturned; P, Q, R are turned next to
// N, and each equatorial face is unturned next to its equatorial neighbours.
//
// Only the four edge strips are filled: the quadrants diagonally beyond the anchor's corners are
// gaps (three faces meet at a cube corner, so two neighbours there would overlap), and the face
// opposite the anchor has no place.
#pragma once

#include <array>
#include <optional>

#include "core/grid.h"

namespace maquette {

class UnfoldedFaces {
 public:
  // Throws maquette::Error for a level outside 0..60 or one the grid does not wrap at.
  UnfoldedFaces(const Grid& grid, int anchor_face, int level);

  int anchor() const { return anchor_; }
  int level() const { return level_; }

  // Whether `face` has a place: the anchor or one of its four edge neighbours.
  bool places(int face) const;
  // Whether two faces share an edge (whatever the anchor).
  static bool adjacent(const Grid& grid, int a, int b);

  // The anchor-frame coordinates of (col, row) of `face` (fractional, pixel centres at integers:
  // the same rigid map takes pixels to pixels); nullopt when the face has no place.
  std::optional<std::array<double, 2>> to_anchor(int face, double col, double row) const;
  std::optional<FaceCoord> to_anchor(FaceCoord pixel) const;
  // The face pixel at anchor-frame (col, row): the anchor's own inside it, a neighbour's in an edge
  // strip; nullopt in the corner gaps and beyond one face width.
  std::optional<FaceCoord> from_anchor(int64_t col, int64_t row) const;
  // A point of a face in fractional pixel coordinates (pixel centres at integers).
  struct FacePoint {
    int face = 0;
    double col = 0, row = 0;
  };
  // The face point at fractional anchor-frame (col, row): mapped through its nearest pixel (at
  // most half a pixel away on each axis, so the point lies on that pixel's face); on a boundary
  // between pixels, through the first of the nearest that has a place (left before right, above
  // before below), so a point on a seam or beside a corner gap is read on a face that holds it;
  // nullopt when none has.
  std::optional<FacePoint> from_anchor(double col, double row) const;

  // Where the tile of `cell` (`size` pixels a side, level() = cell level + log2(size)) lies: its
  // pixel (c, r) at anchor-frame first + c * col_step + r * row_step; nullopt when its face has
  // no place.
  struct TilePlace {
    std::array<int64_t, 2> first, col_step, row_step;

    // The anchor-frame pixel of the tile's pixel (c, r), and the tile's pixel at anchor-frame q
    // (the steps are a rotation: its inverse is its transpose).
    std::array<int64_t, 2> at(int64_t c, int64_t r) const {
      return {first[0] + c * col_step[0] + r * row_step[0],
              first[1] + c * col_step[1] + r * row_step[1]};
    }
    std::array<int64_t, 2> tile_pixel(const std::array<int64_t, 2>& q) const {
      const int64_t dc = q[0] - first[0], dr = q[1] - first[1];
      return {dc * col_step[0] + dr * col_step[1], dc * row_step[0] + dr * row_step[1]};
    }
  };
  std::optional<TilePlace> place_tile(CellId cell, int size) const;

 private:
  // Face pixel p of a neighbour = at + turn * (q - strip), for anchor-frame q in its strip.
  struct Placement {
    int face = -1;
    std::array<int64_t, 2> strip{}, at{};
    std::array<std::array<int64_t, 2>, 2> turn{};  // rows of a rotation matrix
  };

  // The edge strip (0..3: top, right, bottom, left) holding anchor-frame (col, row), kAnchorStrip
  // inside the anchor, nullopt in the corner gaps and beyond one face width.
  static constexpr size_t kAnchorStrip = 4;
  std::optional<size_t> strip_at(int64_t col, int64_t row) const;

  int anchor_, level_;
  int64_t n_;
  std::array<Placement, 4> edges_;  // top, right, bottom, left of the anchor
};

}  // namespace maquette
