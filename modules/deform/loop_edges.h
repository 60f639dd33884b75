// The edges of a triangle mesh and the triangles on each side, for the Loop masks.
#pragma once

#include <array>
#include <span>
#include <vector>

namespace maquette::deform {

struct MeshEdges {
  // Per edge: its end vertices, in the order of its first triangle, and its triangles: the first
  // one, then the one on the other side or -1 (an edge of the border of the triangles given).
  std::vector<std::array<int, 2>> vertices;
  std::vector<std::array<int, 2>> triangles;
  // Per triangle: edge i joins its corners i and (i + 1) % 3 (the opposite corner is (i + 2) % 3).
  std::vector<std::array<int, 3>> triangle_edges;
};

// Edges numbered in the order the triangles first reach them (deterministic).
// Preconditions (std::invalid_argument naming the triangles and vertices otherwise): corners in
// [0, vertex_count) and distinct; every edge in at most two triangles, which run along it in
// opposite directions (an oriented 2-manifold, possibly with border).
MeshEdges mesh_edges(std::span<const std::array<int, 3>> triangles, int vertex_count);

}  // namespace maquette::deform
