#include "core/unfolded_faces.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "core/error.h"

namespace maquette {

UnfoldedFaces::UnfoldedFaces(const Grid& grid, int anchor_face, int level)
    : anchor_(anchor_face), level_(level), n_(0) {
  if (level < 0 || level > 60)
    throw Error("unfolded faces: level " + std::to_string(level) + " is not in 0..60");
  n_ = int64_t(1) << level;
  // Per edge (top, right, bottom, left): a pixel of its strip, and the column and row steps that
  // stay in the strip at a level of at least 2 pixels a side, where the neighbour's turn (the
  // same at every level) is read off Grid::wrap.
  const auto strip = [](int64_t n) {
    return std::array<std::array<int64_t, 2>, 4>{{{0, -1}, {n, 0}, {0, n}, {-1, 0}}};
  };
  const std::array<int64_t, 4> col_step = {1, 1, 1, -1}, row_step = {-1, 1, 1, 1};
  const int turn_level = std::max(level, 1);
  for (size_t e = 0; e < 4; ++e) {
    const auto wrapped = [&](int at_level, int64_t dc, int64_t dr) {
      const std::array<int64_t, 2> q = strip(int64_t(1) << at_level)[e];
      const auto p = grid.wrap({anchor_face, q[0] + dc, q[1] + dr}, at_level);
      if (!p)
        throw Error("unfolded faces: the grid does not wrap beyond face " +
                    std::to_string(anchor_face) + " at level " + std::to_string(at_level));
      return *p;
    };
    const FaceCoord at = wrapped(level, 0, 0), corner = wrapped(turn_level, 0, 0),
                    along = wrapped(turn_level, col_step[e], 0),
                    deeper = wrapped(turn_level, 0, row_step[e]);
    Placement& p = edges_[e];
    p.face = at.face;
    p.strip = strip(n_)[e];
    p.at = {at.col, at.row};
    // Columns of the map: the images of a unit step in col and in row.
    p.turn = {{{(along.col - corner.col) * col_step[e], (deeper.col - corner.col) * row_step[e]},
               {(along.row - corner.row) * col_step[e], (deeper.row - corner.row) * row_step[e]}}};
  }
}

bool UnfoldedFaces::places(int face) const {
  if (face == anchor_) return true;
  for (const Placement& p : edges_)
    if (p.face == face) return true;
  return false;
}

bool UnfoldedFaces::adjacent(const Grid& grid, int a, int b) {
  return a != b && UnfoldedFaces(grid, a, 1).places(b);
}

std::optional<std::array<double, 2>> UnfoldedFaces::to_anchor(int face, double col,
                                                              double row) const {
  if (face == anchor_) return std::array<double, 2>{col, row};
  for (const Placement& p : edges_) {
    if (p.face != face) continue;
    // The map is a rotation: its inverse is its transpose.
    const double dc = col - double(p.at[0]), dr = row - double(p.at[1]);
    return std::array<double, 2>{
        double(p.strip[0]) + double(p.turn[0][0]) * dc + double(p.turn[1][0]) * dr,
        double(p.strip[1]) + double(p.turn[0][1]) * dc + double(p.turn[1][1]) * dr};
  }
  return std::nullopt;
}

std::optional<FaceCoord> UnfoldedFaces::to_anchor(FaceCoord pixel) const {
  const auto q = to_anchor(pixel.face, double(pixel.col), double(pixel.row));
  if (!q) return std::nullopt;
  return FaceCoord{anchor_, int64_t((*q)[0]), int64_t((*q)[1])};
}

std::optional<size_t> UnfoldedFaces::strip_at(int64_t col, int64_t row) const {
  const bool col_in = col >= 0 && col < n_, row_in = row >= 0 && row < n_;
  if (col_in && row_in) return kAnchorStrip;
  if (col_in && row >= -n_ && row < 0) return 0;
  if (row_in && col >= n_ && col < 2 * n_) return 1;
  if (col_in && row >= n_ && row < 2 * n_) return 2;
  if (row_in && col >= -n_ && col < 0) return 3;
  return std::nullopt;
}

std::optional<FaceCoord> UnfoldedFaces::from_anchor(int64_t col, int64_t row) const {
  const auto e = strip_at(col, row);
  if (!e) return std::nullopt;
  if (*e == kAnchorStrip) return FaceCoord{anchor_, col, row};
  const Placement& p = edges_[*e];
  const int64_t dc = col - p.strip[0], dr = row - p.strip[1];
  return FaceCoord{p.face, p.at[0] + p.turn[0][0] * dc + p.turn[0][1] * dr,
                   p.at[1] + p.turn[1][0] * dc + p.turn[1][1] * dr};
}

std::optional<UnfoldedFaces::FacePoint> UnfoldedFaces::from_anchor(double col, double row) const {
  // The nearest pixel: the two nearest when the point is on a boundary between pixels.
  const auto c_low = int64_t(std::ceil(col - 0.5)), c_high = int64_t(std::floor(col + 0.5));
  const auto r_low = int64_t(std::ceil(row - 0.5)), r_high = int64_t(std::floor(row + 0.5));
  for (const auto& [c, r] :
       {std::pair{c_low, r_low}, {c_high, r_low}, {c_low, r_high}, {c_high, r_high}}) {
    const auto e = strip_at(c, r);
    if (!e) continue;
    if (*e == kAnchorStrip) return FacePoint{anchor_, col, row};
    // The pixel's face coordinates plus the offset from its centre, turned as the face is.
    const FaceCoord pixel = *from_anchor(c, r);
    const auto& turn = edges_[*e].turn;
    const double oc = col - double(c), orow = row - double(r);
    return FacePoint{pixel.face,
                     double(pixel.col) + double(turn[0][0]) * oc + double(turn[0][1]) * orow,
                     double(pixel.row) + double(turn[1][0]) * oc + double(turn[1][1]) * orow};
  }
  return std::nullopt;
}

std::optional<UnfoldedFaces::TilePlace> UnfoldedFaces::place_tile(CellId cell, int size) const {
  const int64_t col = int64_t(cell.col()) * size, row = int64_t(cell.row()) * size;
  const auto first = to_anchor({cell.face(), col, row});
  const auto right = to_anchor({cell.face(), col + 1, row});
  const auto below = to_anchor({cell.face(), col, row + 1});
  if (!first || !right || !below) return std::nullopt;
  return TilePlace{{first->col, first->row},
                   {right->col - first->col, right->row - first->row},
                   {below->col - first->col, below->row - first->row}};
}

}  // namespace maquette
