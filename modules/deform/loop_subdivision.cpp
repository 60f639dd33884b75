#include "loop_subdivision.h"

#include <stdexcept>

#include "loop_edges.h"
#include "loop_refine.h"

namespace maquette::deform {

LoopLevel loop_subdivide(const TriangleMesh& coarse) {
  if (coarse.triangles.empty()) {
    throw std::invalid_argument("Loop subdivision: the mesh has no triangle");
  }
  const auto vertex_count = static_cast<int>(coarse.vertices.rows());
  const MeshEdges edges = mesh_edges(coarse.triangles, vertex_count);
  std::vector<bool> on_border(edges.triangles.size());
  for (std::size_t e = 0; e < on_border.size(); ++e) on_border[e] = edges.triangles[e][1] < 0;
  LoopRefinement refinement =
      refine_loop(coarse.triangles, edges, on_border,
                  std::vector<bool>(coarse.triangles.size(), true), vertex_count);
  LoopLevel fine;
  fine.mesh.vertices = refinement.subdivision * coarse.vertices;
  fine.mesh.triangles = std::move(refinement.children);
  fine.subdivision = std::move(refinement.subdivision);
  fine.new_vertex_ends = std::move(refinement.new_vertex_ends);
  return fine;
}

}  // namespace maquette::deform
