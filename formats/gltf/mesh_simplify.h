// Meshes for the coarser levels of a mesh layer (content/content_overviews.h): a parent cell's
// content from its children's, object by object, with meshoptimizer (MIT).
#pragma once

#include <span>
#include <string>

#include "content/content.h"
#include "content/content_overviews.h"

namespace maquette {

// The children's objects (in child order, then their order) in the frame of level.origin:
// - positions re-expressed through ECEF in double (content/enu_transform.h), normals turned
//   with the frame; uvs, material and provenance kept;
// - an object whose bounding box has a diagonal below level.sample_m is dropped (it would cover
//   less than a sample);
// - each object simplified by meshopt_simplify (edge collapses, quadric error) towards a
//   quarter of its triangles, moving its surface by at most half of level.sample_m as
//   meshoptimizer measures it: the coarsenings of successive levels (samples doubling each
//   level up) then add up to less than the level's sample (1/2 + 1/4 + ...). It stops earlier
//   where that bound forbids more; an object left with no triangle is dropped. A closed,
//   outward solid (content/closed_solid.h: buildings, bridge decks) stays one, with no crossing
//   triangles: when the result is not, the bound is halved (at most three times) and, failing
//   that, the object is kept whole, so that a view from afar never sees through a roof. A solid
//   with facet normals (content/facet_normals.h: every corner's normal its face's within 2
//   degrees, triangles under 10 cm high aside; buildings, bridge decks, prisms; each corner one
//   vertex per face, which edge collapses cannot merge) is simplified with its vertices at one
//   position and texture coordinate welded, within a quarter of that bound (an eighth of the
//   sample: a corner collapsed within half a sample cuts its footprint, and the ground would
//   show through its roof from afar), and its facet normals are made again for the faces left;
//   smooth normals are kept. Vertices are renumbered in the order the triangles first use them
//   (an object kept whole keeps its own);
// - materials merged (equal ones, images included, become one), each image halved in both
//   directions (OpenCV, area averaging; at least 1 pixel) and encoded again in its own format.
// Deterministic: the same children give the same content.
MeshContent simplify_mesh_children(std::span<const MeshContent> children,
                                   const ContentLevel& level);

// An encoded image (JPEG, PNG or WebP) at half its width and height, in its own format. Throws
// maquette::Error naming `where` for bytes OpenCV cannot decode.
std::string halve_image(const std::string& image, const std::string& mime,
                        const std::string& where);

}  // namespace maquette
