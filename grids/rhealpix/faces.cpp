#include "faces.h"

#include <array>

#include "projection.h"

namespace maquette {
namespace {

enum Edge { kTop = 0, kRight, kBottom, kLeft };

struct EdgeLink {
  int face;
  int edge;
};

// kAdjacent[face][edge]: the face across that edge and the edge it shares. Every edge is
// parametrised clockwise around its face, so the two faces run along it in opposite directions.
constexpr std::array<std::array<EdgeLink, 4>, 6> kAdjacent = {{
    {{{kFaceQ, kTop}, {kFaceP, kTop}, {kFaceO, kTop}, {kFaceR, kTop}}},              // N
    {{{kFaceN, kBottom}, {kFaceP, kLeft}, {kFaceS, kTop}, {kFaceR, kRight}}},        // O
    {{{kFaceN, kRight}, {kFaceQ, kLeft}, {kFaceS, kRight}, {kFaceO, kRight}}},       // P
    {{{kFaceN, kTop}, {kFaceR, kLeft}, {kFaceS, kBottom}, {kFaceP, kRight}}},        // Q
    {{{kFaceN, kLeft}, {kFaceO, kLeft}, {kFaceS, kLeft}, {kFaceQ, kRight}}},         // R
    {{{kFaceO, kBottom}, {kFaceP, kBottom}, {kFaceQ, kBottom}, {kFaceR, kBottom}}},  // S
}};

// Moves c across `edge` of its face: position t along the edge (clockwise) and depth beyond
// it, then the same depth inside the neighbour at position n - 1 - t along its edge.
FaceCoord cross(FaceCoord c, int64_t n, int edge) {
  int64_t t = 0;
  int64_t depth = 0;
  switch (edge) {
    case kTop:
      t = c.col, depth = -c.row - 1;
      break;
    case kRight:
      t = c.row, depth = c.col - n;
      break;
    case kBottom:
      t = n - 1 - c.col, depth = c.row - n;
      break;
    default:
      t = n - 1 - c.row, depth = -c.col - 1;
      break;
  }
  const EdgeLink link = kAdjacent[size_t(c.face)][size_t(edge)];
  const int64_t s = n - 1 - t;
  switch (link.edge) {
    case kTop:
      return {link.face, s, depth};
    case kRight:
      return {link.face, n - 1 - depth, s};
    case kBottom:
      return {link.face, n - 1 - s, n - 1 - depth};
    default:
      return {link.face, depth, n - 1 - s};
  }
}

// Cells beyond the lower (negative) or upper edge, -1 when inside.
int64_t beyond(int64_t x, int64_t n) { return x < 0 ? -x - 1 : x >= n ? x - n : -1; }

// Crosses the column edge if c is beyond it (and, beyond a corner, at least as far as beyond
// the row edge), else the row edge if c is beyond that.
FaceCoord cross_one(FaceCoord c, int64_t n) {
  const int64_t a = beyond(c.col, n);
  const int64_t b = beyond(c.row, n);
  if (a >= 0 && a >= b) return cross(c, n, c.col < 0 ? kLeft : kRight);
  if (b >= 0) return cross(c, n, c.row < 0 ? kTop : kBottom);
  return c;
}

}  // namespace

std::optional<FaceCoord> wrap_face_coord(FaceCoord c, int level) {
  const int64_t n = int64_t(1) << level;
  if (c.col < -n || c.col >= 2 * n || c.row < -n || c.row >= 2 * n) return std::nullopt;
  // Beyond a corner the first crossing leaves c beyond one edge of the neighbour face.
  return cross_one(cross_one(c, n), n);
}

}  // namespace maquette
