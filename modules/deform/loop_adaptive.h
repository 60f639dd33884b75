// Incremental adaptive Loop subdivision (paper 002, §3.2, after Pakdel and Samavati 2004): only
// the triangles near the features are subdivided, level after level, and neighbouring triangles
// stay at most one level apart, joined without T-junctions by transition triangles.
#pragma once

#include <vector>

#include "loop_mesh.h"

namespace maquette::deform {

struct AdaptiveLoop {
  // meshes[0] is the base mesh; meshes[j + 1].vertices == subdivisions[j] * meshes[j].vertices.
  // A vertex keeps its index from the level it appears at: the rows of subdivisions[j] are
  // identity for the vertices outside the zone refined at step j, Loop's vertex mask for those of
  // the zone, then the new edge vertices (loop_refine.h), so a constraint on meshes[j + 1] is
  // written on the unknowns of meshes[j] through subdivisions[j], as with uniform subdivision.
  std::vector<TriangleMesh> meshes;
  std::vector<SubdivisionMatrix> subdivisions;
  // Per step j and new vertex (meshes[j]'s vertex count + i): the ends of the edge it is on.
  std::vector<std::vector<std::array<int, 2>>> new_vertex_ends;
  // Per triangle of meshes[j]: its level (0 for a base triangle, ..., j).
  std::vector<std::vector<int>> triangle_levels;
};

// Subdivides `levels` times the descendants of the `marked` base triangles. At step j (0-based)
// the zone refined is the level-j descendants of marked triangles grown by (levels - 1 - j) rings
// of triangles (those sharing a vertex), so that every vertex of the next zones has its whole
// ring of triangles of the level before: the positions of the vertices of every level-j triangle
// equal those of uniform Loop subdivision at level j (up to rounding). Red closure: a triangle
// with two or three refined edge-neighbours is refined too; one with one is split in two through
// the new vertex of that edge (green, transition triangle, of its own level). Each vertex takes
// the position of the finest level it belongs to, so shared vertices are one vertex: no crack.
// Preconditions (std::invalid_argument otherwise): levels >= 1, marked.size() equal to the
// number of base triangles, and the base mesh as for loop_subdivide (checked around the marked
// triangles: the others are returned as they are).
AdaptiveLoop adaptive_loop_subdivide(const TriangleMesh& base, const std::vector<bool>& marked,
                                     int levels);

}  // namespace maquette::deform
