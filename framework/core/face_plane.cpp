#include "core/face_plane.h"

#include <optional>
#include <string>

#include "core/error.h"
#include "core/unfolded_faces.h"

namespace maquette {

namespace {

using Offset = std::array<int64_t, 2>;
constexpr int kFaces = CellId::kNumFaces;

}  // namespace

FacePlane::FacePlane(const Grid& grid) {
  // beside[a][b]: where face b lies in face a's frame, in face widths, when it meets a unturned.
  std::array<std::array<std::optional<Offset>, kFaces>, kFaces> beside{};
  for (int a = 0; a < kFaces; ++a) {
    const UnfoldedFaces unfolded(grid, a, 0);
    for (int b = 0; b < kFaces; ++b) {
      const auto p = b == a ? std::nullopt : unfolded.place_tile(CellId::FromFace(b), 1);
      if (p && p->col_step == Offset{1, 0} && p->row_step == Offset{0, 1})
        beside[size_t(a)][size_t(b)] = p->first;
    }
  }
  const auto face_at = [&](int a, const Offset& offset) {
    for (int b = 0; b < kFaces; ++b)
      if (beside[size_t(a)][size_t(b)] == offset) return b;
    return -1;
  };
  // The row starts at the face with a face unturned above it, and runs rightwards.
  int start = -1;
  for (int a = 0; a < kFaces && start < 0; ++a)
    if (face_at(a, {0, -1}) >= 0 && face_at(a, {1, 0}) >= 0) start = a;
  std::array<bool, kFaces> placed{};
  int f = start;
  for (; f >= 0 && !placed[size_t(f)]; f = face_at(f, {1, 0})) {
    ring_order_[size_t(ring_faces_)] = f;
    places_[size_t(f)] = {ring_faces_++, 0};
    placed[size_t(f)] = true;
  }
  if (start < 0 || f != start || ring_faces_ < 2)
    throw Error("face plane: the grid's faces form no row laid unturned side by side");
  // The others above or below the row's face they meet unturned.
  const std::array<bool, kFaces> in_row = placed;
  for (int p = 0; p < kFaces; ++p)
    for (int r = 0; r < kFaces && !placed[size_t(p)]; ++r)
      for (const int64_t side : {-1, 1})
        if (in_row[size_t(r)] && beside[size_t(r)][size_t(p)] == Offset{0, side}) {
          places_[size_t(p)] = {places_[size_t(r)][0], side};
          placed[size_t(p)] = true;
        }
  for (int face = 0; face < kFaces; ++face)
    if (!placed[size_t(face)])
      throw Error("face plane: face " + std::to_string(face) +
                  " meets no face of the row unturned");
}

std::array<int64_t, 2> FacePlane::tile_pixel(CellId cell, int size, int64_t col,
                                             int64_t row) const {
  const int64_t n = int64_t(size) << cell.level();
  const Offset& p = place(cell.face());
  return {p[0] * n + int64_t(cell.col()) * size + col, p[1] * n + int64_t(cell.row()) * size + row};
}

int64_t FacePlane::wrap_columns(CellId cell, int size) const {
  return ring_faces_ * (int64_t(size) << cell.level());
}

std::optional<FaceCoord> FacePlane::chart_pixel(const Grid& grid, int face, int level, int64_t col,
                                                int64_t row) const {
  const int64_t n = int64_t(1) << level;
  const bool col_in = col >= 0 && col < n, row_in = row >= 0 && row < n;
  if (col_in && row_in) return FaceCoord{face, col, row};
  if (col < -n || col >= 2 * n || row < -n || row >= 2 * n) return std::nullopt;
  const Offset& p = place(face);
  const int64_t y = p[1] * n + row;  // the plane's row
  // Beyond one edge, or a polar face's corner away from the row: the store's halo.
  if (col_in || row_in || (p[1] != 0 && (y < 0 || y >= n)))
    return grid.wrap({face, col, row}, level);
  const int64_t ring = ring_faces_ * n;
  const int64_t x = ((p[0] * n + col) % ring + ring) % ring;
  const int f = ring_order_[size_t(x / n)];
  const FaceCoord across{f, x % n, y};
  if (y >= 0 && y < n) return across;
  return grid.wrap(across, level);
}

}  // namespace maquette
