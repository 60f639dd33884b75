// Whether a mesh object is a solid a viewer can draw with back faces culled: closed and turned
// outward, so that no view sees through it (content overviews keep it so: gltf/mesh_simplify.h).
#pragma once

#include "content/content.h"

namespace maquette {

// True when `object`, its vertices at one position (equal floats) taken as one point, is a
// closed, consistently oriented shell (every directed edge used exactly once, and its reverse
// exactly once; no triangle with two corners at one point) enclosing a positive volume (its
// triangles counter-clockwise seen from outside). Empty objects are not solids.
bool is_closed_outward(const MeshObject& object);

// The triangles of `object` (its indices) less its fins: pairs of triangles on the same three
// points turned opposite ways, back to back, enclosing nothing (edge collapses leave some).
// The other triangles keep their order.
std::vector<uint32_t> without_fins(const MeshObject& object);

// True when two triangles of `object` cross: an edge of one passes through the other's interior
// strictly (orientations in double: touching, coplanar overlaps and near-degenerate cases within
// rounding are not counted). Triangles sharing an edge are never counted; triangles sharing one
// point are tested with the edge opposite it. Vertices at one position are one point. Pairs of
// triangles found by a sweep of their bounding boxes along x: near n log n for surfaces spread
// out (a lake), O(n^2) at worst.
bool has_crossing_triangles(const MeshObject& object);

}  // namespace maquette
