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
// triangle uses it); positions are unchanged. Deterministic. Degenerate triangles (no area, or
// slivers lower than kFacetMinHeightM over their longest side: the content overviews' edge
// collapses leave such triangles closing T-junctions of a flat face, their own normal pointing
// anywhere) take the first orientation of each vertex's other faces (up, +z, when there is
// none), so that they share their neighbours' vertices; a vertex no triangle uses keeps one copy
// facing up. Time linear in the corners (times the orientations at a vertex); ~50 bytes of
// temporaries per triangle. In parallel (TBB) by triangles and by vertices: the same object for
// any thread count.
// Precondition: indices within positions, fewer than 2^32 corners, normals empty.
inline constexpr double kFacetNormalTurnDeg = 1;
// Metres: the store's GLB rounds each coordinate to the millimetre (gltf/mesh_glb.h), which can
// lift a flat triangle's corner sqrt(3) mm off the line of the other two, turning a triangle
// lower than that by any angle.
inline constexpr double kFacetMinHeightM = 1.7321e-3;
MeshObject with_facet_normals(const MeshObject& object);

}  // namespace maquette
