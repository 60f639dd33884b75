// Uniform Loop subdivision as sparse matrices (paper 002, §3.2, Eq. 1-4): V_{k+1} = S_k V_k, so a
// constraint on the surface at level k+1 is a row of S_k (or of a product of the S's) acting on
// the vertices of level k.
#pragma once

#include "loop_mesh.h"

namespace maquette::deform {

struct LoopLevel {
  TriangleMesh mesh;
  // mesh.vertices == subdivision * (the coarser mesh's vertices); rows: the coarser mesh's
  // vertices (same indices, moved by the vertex masks), then one new vertex per edge, in the order
  // the triangles reach their edges (loop_edges.h).
  SubdivisionMatrix subdivision;
  // Per new vertex (the coarser vertex count + i): the ends of the coarser edge it is on.
  std::vector<std::array<int, 2>> new_vertex_ends;
};

// One level of Loop subdivision of the whole mesh (masks and the children's order: loop_refine.h):
// triangle t becomes triangles 4t .. 4t+3 of the result. Border vertices and edges follow the
// cubic B-spline of the border (3/4, 1/8, 1/8 and 1/2, 1/2), as OpenMesh's LoopT does.
// Preconditions (std::invalid_argument otherwise): an oriented 2-manifold, possibly with border
// (mesh_edges), every border vertex on exactly two border edges, at least one triangle.
LoopLevel loop_subdivide(const TriangleMesh& coarse);

}  // namespace maquette::deform
