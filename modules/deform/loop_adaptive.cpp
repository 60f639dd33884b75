#include "loop_adaptive.h"

#include <stdexcept>
#include <string>

#include "loop_edges.h"
#include "loop_refine.h"

namespace maquette::deform {
namespace {

// Adds to `refined` the triangles sharing a vertex with a refined one.
void grow_by_one_ring(std::span<const std::array<int, 3>> triangles, int vertex_count,
                      std::vector<bool>& refined) {
  std::vector<bool> touched(static_cast<std::size_t>(vertex_count), false);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    if (!refined[t]) continue;
    for (const int v : triangles[t]) touched[static_cast<std::size_t>(v)] = true;
  }
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (const int v : triangles[t]) {
      if (touched[static_cast<std::size_t>(v)]) refined[t] = true;
    }
  }
}

int refined_neighbours(const MeshEdges& edges, const std::vector<bool>& refined, std::size_t t) {
  int count = 0;
  for (const int e : edges.triangle_edges[t]) {
    for (const int side : edges.triangles[static_cast<std::size_t>(e)]) {
      if (side >= 0 && static_cast<std::size_t>(side) != t &&
          refined[static_cast<std::size_t>(side)]) {
        ++count;
      }
    }
  }
  return count;
}

// Red closure: refines every triangle with two or three refined edge-neighbours, until none is
// left (its vertices are all on refined triangles, so their rings are there).
void close_red(const MeshEdges& edges, std::vector<bool>& refined) {
  std::vector<std::size_t> pending(refined.size());
  for (std::size_t t = 0; t < pending.size(); ++t) pending[t] = t;
  while (!pending.empty()) {
    const std::size_t t = pending.back();
    pending.pop_back();
    if (refined[t] || refined_neighbours(edges, refined, t) < 2) continue;
    refined[t] = true;
    for (const int e : edges.triangle_edges[t]) {
      for (const int side : edges.triangles[static_cast<std::size_t>(e)]) {
        if (side >= 0) pending.push_back(static_cast<std::size_t>(side));
      }
    }
  }
}

}  // namespace

AdaptiveLoop adaptive_loop_subdivide(const TriangleMesh& base, const std::vector<bool>& marked,
                                     int levels) {
  if (levels < 1) {
    throw std::invalid_argument("adaptive Loop subdivision: levels must be >= 1, got " +
                                std::to_string(levels));
  }
  if (marked.size() != base.triangles.size()) {
    throw std::invalid_argument("adaptive Loop subdivision: marked has " +
                                std::to_string(marked.size()) + " flags for " +
                                std::to_string(base.triangles.size()) + " triangles");
  }
  AdaptiveLoop out;
  out.meshes.push_back(base);
  out.triangle_levels.emplace_back(base.triangles.size(), 0);

  // The zone: the triangles of the current level (the marked base triangles grown by `levels`
  // rings, then the children of the last refined ones); per triangle edge, whether it is on the
  // border of the whole surface. Step 0's refinement and red closure stay inside the first zone
  // (they touch only vertices of the marked triangles grown by levels - 1 rings); the other base
  // triangles are final. A zone edge with no other triangle in one ring more is on the border.
  const auto base_vertices = static_cast<int>(base.vertices.rows());
  std::vector<bool> in_zone = marked;
  for (int ring = 0; ring < levels; ++ring)
    grow_by_one_ring(base.triangles, base_vertices, in_zone);
  std::vector<bool> in_halo = in_zone;
  grow_by_one_ring(base.triangles, base_vertices, in_halo);
  std::vector<std::array<int, 3>> halo;
  std::vector<std::size_t> halo_base;        // base index of each halo triangle
  std::vector<std::array<int, 3>> finished;  // triangles of coarser levels, no more refined
  for (std::size_t t = 0; t < base.triangles.size(); ++t) {
    if (in_halo[t]) {
      halo.push_back(base.triangles[t]);
      halo_base.push_back(t);
    }
    if (!in_zone[t]) finished.push_back(base.triangles[t]);
  }
  std::vector<int> finished_levels(finished.size(), 0);
  std::vector<std::array<int, 3>> zone;
  std::vector<std::array<bool, 3>> zone_border;
  std::vector<bool> wanted;
  const MeshEdges halo_edges = mesh_edges(halo, base_vertices);
  for (std::size_t h = 0; h < halo.size(); ++h) {
    if (!in_zone[halo_base[h]]) continue;
    zone.push_back(halo[h]);
    wanted.push_back(marked[halo_base[h]]);
    std::array<bool, 3> border{};
    for (std::size_t i = 0; i < 3; ++i) {
      border[i] =
          halo_edges.triangles[static_cast<std::size_t>(halo_edges.triangle_edges[h][i])][1] < 0;
    }
    zone_border.push_back(border);
  }

  for (int level = 0; level < levels; ++level) {
    const TriangleMesh& coarse = out.meshes.back();
    const auto vertex_count = static_cast<int>(coarse.vertices.rows());
    const MeshEdges edges = mesh_edges(zone, vertex_count);
    std::vector<bool> on_border(edges.vertices.size(), false);
    for (std::size_t t = 0; t < zone.size(); ++t) {
      for (std::size_t i = 0; i < 3; ++i) {
        if (zone_border[t][i])
          on_border[static_cast<std::size_t>(edges.triangle_edges[t][i])] = true;
      }
    }
    std::vector<bool> refined = wanted;
    for (int ring = 0; ring < levels - 1 - level; ++ring) {
      grow_by_one_ring(zone, vertex_count, refined);
    }
    close_red(edges, refined);
    LoopRefinement refinement = refine_loop(zone, edges, on_border, refined, vertex_count);

    for (std::size_t t = 0; t < zone.size(); ++t) {
      if (refined[t]) continue;
      int split_edge = -1;
      int split_edges = 0;
      for (int i = 0; i < 3; ++i) {
        const int e = edges.triangle_edges[t][static_cast<std::size_t>(i)];
        if (refinement.edge_vertex[static_cast<std::size_t>(e)] >= 0) {
          split_edge = i;
          ++split_edges;
        }
      }
      if (split_edges > 1) {
        throw std::logic_error("adaptive Loop subdivision: red closure left a triangle with " +
                               std::to_string(split_edges) + " split edges");
      }
      if (split_edge < 0) {
        finished.push_back(zone[t]);
        finished_levels.push_back(level);
        continue;
      }
      // Green: halves through the new vertex m of edge (a, b), towards the opposite corner o.
      const auto i = static_cast<std::size_t>(split_edge);
      const int a = zone[t][i];
      const int b = zone[t][(i + 1) % 3];
      const int o = zone[t][(i + 2) % 3];
      const int m = refinement.edge_vertex[static_cast<std::size_t>(edges.triangle_edges[t][i])];
      finished.push_back({a, m, o});
      finished.push_back({m, b, o});
      finished_levels.insert(finished_levels.end(), 2, level);
    }

    std::vector<std::array<bool, 3>> children_border;
    std::vector<bool> children_wanted;
    for (std::size_t t = 0; t < zone.size(); ++t) {
      if (!refined[t]) continue;
      const auto [ab, bc, ca] = zone_border[t];
      children_border.push_back({ab, false, ca});
      children_border.push_back({ab, bc, false});
      children_border.push_back({false, bc, ca});
      children_border.push_back({false, false, false});
      children_wanted.insert(children_wanted.end(), 4, wanted[t]);
    }
    zone = std::move(refinement.children);
    zone_border = std::move(children_border);
    wanted = std::move(children_wanted);

    TriangleMesh fine;
    fine.vertices = refinement.subdivision * coarse.vertices;
    fine.triangles = finished;
    fine.triangles.insert(fine.triangles.end(), zone.begin(), zone.end());
    std::vector<int> fine_levels = finished_levels;
    fine_levels.insert(fine_levels.end(), zone.size(), level + 1);
    out.meshes.push_back(std::move(fine));
    out.subdivisions.push_back(std::move(refinement.subdivision));
    out.new_vertex_ends.push_back(std::move(refinement.new_vertex_ends));
    out.triangle_levels.push_back(std::move(fine_levels));
  }
  return out;
}

}  // namespace maquette::deform
