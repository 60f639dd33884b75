// One step of Loop subdivision over chosen triangles of a mesh, as a sparse matrix: the masks
// shared by the uniform (loop_subdivision.h) and the adaptive (loop_adaptive.h) subdivisions.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "loop_edges.h"
#include "loop_mesh.h"

namespace maquette::deform {

struct LoopRefinement {
  // Four children per refined triangle (a, b, c) with new edge vertices ab, bc, ca, in the order
  // of the refined triangles: (a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca). Child edges on
  // the parent's edge i keep its index i (corner order above), so children inherit border flags.
  std::vector<std::array<int, 3>> children;
  // Per edge of the mesh: the new vertex on it, -1 when no refined triangle has it.
  std::vector<int> edge_vertex;
  // Per new vertex (vertex_count + i): the ends of the edge it is on.
  std::vector<std::array<int, 2>> new_vertex_ends;
  // (vertex_count + new vertices) x vertex_count: fine = subdivision * coarse. Vertices of the
  // refined triangles (even) take Loop's vertex mask, new edge vertices (odd) the edge mask, any
  // other vertex is kept (identity row). New vertices are numbered from vertex_count in the order
  // the refined triangles reach their edges.
  SubdivisionMatrix subdivision;
};

// Loop's masks (Loop 1987; the weights of Warren's and OpenMesh's LoopT):
//   inner vertex of valence n:  (1 - n b) v + b sum(neighbours), b = (5/8 - (3/8 + cos(2
//   pi/n)/4)^2) / n border vertex:              3/4 v + 1/8 (its two neighbours along the border)
//   inner edge (a, b), opposite c, d:  3/8 (a + b) + 1/8 (c + d)
//   border edge (a, b):         1/2 (a + b)
// (the border masks are those of the cubic B-spline along the border curve). `on_border[e]` tells
// whether edge e is on the border of the whole surface; the triangles given may be part of it.
// Preconditions: every vertex of a refined triangle has all its triangles of the whole surface
// among `triangles` (std::logic_error otherwise: the caller chose its triangles wrong) and, on the
// border, exactly two border edges (std::invalid_argument otherwise: a non-manifold vertex).
LoopRefinement refine_loop(std::span<const std::array<int, 3>> triangles, const MeshEdges& edges,
                           const std::vector<bool>& on_border, const std::vector<bool>& refined,
                           int vertex_count);

}  // namespace maquette::deform
