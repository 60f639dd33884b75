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

// The triangles of the level being refined; per triangle edge, whether it is on the border of
// the whole surface; per triangle, whether it descends from a marked base triangle.
struct Zone {
  std::vector<std::array<int, 3>> triangles;
  std::vector<std::array<bool, 3>> border;
  std::vector<bool> wanted;
};

// Triangles of coarser levels, no more refined, and their levels.
struct Finished {
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> levels;
};

// The marked base triangles grown by `levels` rings: step 0's refinement and red closure touch
// only vertices of the marked triangles grown by levels - 1 rings, so they stay inside. The other
// base triangles are final (added to `finished`). A zone edge with no other triangle in one ring
// more is on the surface's border.
Zone first_zone(const TriangleMesh& base, const std::vector<bool>& marked, int levels,
                Finished& finished) {
  const auto base_vertices = static_cast<int>(base.vertices.rows());
  std::vector<bool> in_zone = marked;
  for (int ring = 0; ring < levels; ++ring) {
    grow_by_one_ring(base.triangles, base_vertices, in_zone);
  }
  std::vector<bool> in_halo = in_zone;
  grow_by_one_ring(base.triangles, base_vertices, in_halo);
  std::vector<std::array<int, 3>> halo;
  std::vector<std::size_t> halo_base;  // base index of each halo triangle
  for (std::size_t t = 0; t < base.triangles.size(); ++t) {
    if (in_halo[t]) {
      halo.push_back(base.triangles[t]);
      halo_base.push_back(t);
    }
    if (!in_zone[t]) finished.triangles.push_back(base.triangles[t]);
  }
  finished.levels.assign(finished.triangles.size(), 0);
  Zone zone;
  const MeshEdges halo_edges = mesh_edges(halo, base_vertices);
  for (std::size_t h = 0; h < halo.size(); ++h) {
    if (!in_zone[halo_base[h]]) continue;
    zone.triangles.push_back(halo[h]);
    zone.wanted.push_back(marked[halo_base[h]]);
    std::array<bool, 3> border{};
    for (std::size_t i = 0; i < 3; ++i) {
      const auto e = static_cast<std::size_t>(halo_edges.triangle_edges[h][i]);
      border[i] = halo_edges.triangles[e][1] < 0;
    }
    zone.border.push_back(border);
  }
  return zone;
}

// Adds the zone's triangles left unrefined to `finished`: as they are, or halved through the new
// vertex of their one split edge (green).
void finish_unrefined(const Zone& zone, const MeshEdges& edges, const std::vector<bool>& refined,
                      const LoopRefinement& refinement, int level, Finished& finished) {
  for (std::size_t t = 0; t < zone.triangles.size(); ++t) {
    if (refined[t]) continue;
    const auto& triangle = zone.triangles[t];
    int split_edges = 0;
    for (std::size_t i = 0; i < 3; ++i) {
      const int m = refinement.edge_vertex[static_cast<std::size_t>(edges.triangle_edges[t][i])];
      if (m < 0) continue;
      if (++split_edges > 1) {
        throw std::logic_error("adaptive Loop subdivision: red closure left a triangle with " +
                               std::to_string(split_edges) + " split edges");
      }
      // Halves through m on edge (a, b), towards the opposite corner o.
      const int a = triangle[i];
      const int b = triangle[(i + 1) % 3];
      const int o = triangle[(i + 2) % 3];
      finished.triangles.push_back({a, m, o});
      finished.triangles.push_back({m, b, o});
      finished.levels.insert(finished.levels.end(), 2, level);
    }
    if (split_edges == 0) {
      finished.triangles.push_back(triangle);
      finished.levels.push_back(level);
    }
  }
}

// The next zone: the children of the refined triangles (loop_refine.h's order), their border
// edges those on their parent's border edges.
Zone children_zone(const Zone& zone, const std::vector<bool>& refined,
                   std::vector<std::array<int, 3>> children) {
  Zone next;
  next.triangles = std::move(children);
  for (std::size_t t = 0; t < zone.triangles.size(); ++t) {
    if (!refined[t]) continue;
    const auto [ab, bc, ca] = zone.border[t];
    next.border.push_back({ab, false, ca});
    next.border.push_back({ab, bc, false});
    next.border.push_back({false, bc, ca});
    next.border.push_back({false, false, false});
    next.wanted.insert(next.wanted.end(), 4, zone.wanted[t]);
  }
  return next;
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
  Finished finished;
  Zone zone = first_zone(base, marked, levels, finished);

  for (int level = 0; level < levels; ++level) {
    const TriangleMesh& coarse = out.meshes.back();
    const auto vertex_count = static_cast<int>(coarse.vertices.rows());
    const MeshEdges edges = mesh_edges(zone.triangles, vertex_count);
    std::vector<bool> on_border(edges.vertices.size(), false);
    for (std::size_t t = 0; t < zone.triangles.size(); ++t) {
      for (std::size_t i = 0; i < 3; ++i) {
        if (zone.border[t][i]) {
          on_border[static_cast<std::size_t>(edges.triangle_edges[t][i])] = true;
        }
      }
    }
    std::vector<bool> refined = zone.wanted;
    for (int ring = 0; ring < levels - 1 - level; ++ring) {
      grow_by_one_ring(zone.triangles, vertex_count, refined);
    }
    close_red(edges, refined);
    LoopRefinement refinement =
        refine_loop(zone.triangles, edges, on_border, refined, vertex_count);
    finish_unrefined(zone, edges, refined, refinement, level, finished);
    zone = children_zone(zone, refined, std::move(refinement.children));

    TriangleMesh fine;
    fine.vertices = refinement.subdivision * coarse.vertices;
    fine.triangles = finished.triangles;
    fine.triangles.insert(fine.triangles.end(), zone.triangles.begin(), zone.triangles.end());
    std::vector<int> fine_levels = finished.levels;
    fine_levels.insert(fine_levels.end(), zone.triangles.size(), level + 1);
    out.meshes.push_back(std::move(fine));
    out.subdivisions.push_back(std::move(refinement.subdivision));
    out.new_vertex_ends.push_back(std::move(refinement.new_vertex_ends));
    out.triangle_levels.push_back(std::move(fine_levels));
  }
  return out;
}

}  // namespace maquette::deform
