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
// orientation; the copies come in the order of their vertices (the first stays first: an
// object's anchor, content.h); positions are unchanged. Deterministic. Degenerate triangles (no
// normal) take the orientation of the first group met at each vertex (up, +z, when there is none).
// Precondition: indices within positions, normals empty.
inline constexpr double kFacetNormalTurnDeg = 1;
MeshObject with_facet_normals(const MeshObject& object);

}  // namespace maquette
