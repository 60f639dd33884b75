// Normals for a mesh drawn with flat faces (buildings, bridge decks): glTF asks viewers to compute
// flat normals for a primitive without any, and CesiumJS draws such a primitive unlit instead, so
// the meshes carry them.
#pragma once

#include "content/content.h"

namespace maquette {

// `object` (no normals yet) with a unit normal per vertex: the normal of the faces around it,
// a vertex whose faces turn by more than kFacetNormalTurnDeg split into one copy per orientation
// (a box's corner into three), uvs copied with it; faces whose normals differ by less (the
// triangles of one planar face) share their vertices. The triangles keep their order and
// orientation; the copies come in the order of their vertices, each vertex's in the order its
// triangles meet them (the first vertex stays first: an object's anchor, content.h, also when no
// triangle uses it); positions are unchanged. Deterministic. Degenerate triangles (no normal)
// take the orientation of the first group met at each vertex (up, +z, when there is none); a
// vertex no triangle uses keeps one copy facing up. Time linear in the corners (times the
// orientations at a vertex); ~50 bytes of temporaries per triangle. In parallel (TBB) by
// triangles and by vertices: the same object for any thread count.
// Precondition: indices within positions, fewer than 2^32 corners, normals empty.
inline constexpr double kFacetNormalTurnDeg = 1;
MeshObject with_facet_normals(const MeshObject& object);

}  // namespace maquette
