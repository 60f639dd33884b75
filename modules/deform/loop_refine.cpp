#include "loop_refine.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace maquette::deform {
namespace {

double inner_neighbour_weight(int valence) {
  const double c = 3.0 / 8.0 + std::cos(2.0 * std::numbers::pi / valence) / 4.0;
  return (5.0 / 8.0 - c * c) / valence;
}

}  // namespace

LoopRefinement refine_loop(std::span<const std::array<int, 3>> triangles, const MeshEdges& edges,
                           const std::vector<bool>& on_border, const std::vector<bool>& refined,
                           int vertex_count) {
  const auto vertices = static_cast<std::size_t>(vertex_count);
  std::vector<bool> even(vertices, false);
  LoopRefinement out;
  out.edge_vertex.assign(edges.vertices.size(), -1);
  int next_vertex = vertex_count;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    if (!refined[t]) continue;
    for (std::size_t i = 0; i < 3; ++i) {
      even[static_cast<std::size_t>(triangles[t][i])] = true;
      const int split_edge_index = edges.triangle_edges[t][i];
      int& split = out.edge_vertex[static_cast<std::size_t>(split_edge_index)];
      if (split < 0) {
        split = next_vertex++;
        out.new_vertex_ends.push_back(edges.vertices[static_cast<std::size_t>(split_edge_index)]);
      }
    }
  }

  // Valences and border edges of the even vertices; a gap in a vertex's fan (an edge with one
  // triangle that is not on the surface's border) means its mask would miss neighbours.
  std::vector<int> valence(vertices, 0);
  std::vector<int> border_edges(vertices, 0);
  for (std::size_t e = 0; e < edges.vertices.size(); ++e) {
    for (const int v : edges.vertices[e]) {
      const auto vi = static_cast<std::size_t>(v);
      if (!even[vi]) continue;
      ++valence[vi];
      if (on_border[e]) {
        ++border_edges[vi];
      } else if (edges.triangles[e][1] < 0) {
        throw std::logic_error("Loop refinement: vertex " + std::to_string(v) +
                               " of a refined triangle lacks triangles around it");
      }
    }
  }

  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(vertices + 7 * static_cast<std::size_t>(next_vertex - vertex_count) * 2);
  std::vector<double> neighbour_weight(vertices, 0.0);
  for (std::size_t v = 0; v < vertices; ++v) {
    const int vi = static_cast<int>(v);
    if (!even[v]) {
      entries.emplace_back(vi, vi, 1.0);
    } else if (border_edges[v] == 0) {
      neighbour_weight[v] = inner_neighbour_weight(valence[v]);
      entries.emplace_back(vi, vi, 1.0 - valence[v] * neighbour_weight[v]);
    } else if (border_edges[v] == 2) {
      entries.emplace_back(vi, vi, 3.0 / 4.0);
    } else {
      throw std::invalid_argument("mesh: vertex " + std::to_string(v) + " has " +
                                  std::to_string(border_edges[v]) +
                                  " border edges (a border vertex needs exactly 2)");
    }
  }
  for (std::size_t e = 0; e < edges.vertices.size(); ++e) {
    const auto [a, b] = edges.vertices[e];
    for (const auto [v, other] : {std::array{a, b}, std::array{b, a}}) {
      const auto vi = static_cast<std::size_t>(v);
      if (!even[vi]) continue;
      if (border_edges[vi] == 0) {
        entries.emplace_back(v, other, neighbour_weight[vi]);
      } else if (on_border[e]) {
        entries.emplace_back(v, other, 1.0 / 8.0);
      }
    }
    const int split = out.edge_vertex[e];
    if (split < 0) continue;
    if (on_border[e]) {
      entries.emplace_back(split, a, 0.5);
      entries.emplace_back(split, b, 0.5);
      continue;
    }
    entries.emplace_back(split, a, 3.0 / 8.0);
    entries.emplace_back(split, b, 3.0 / 8.0);
    for (const int t : edges.triangles[e]) {
      const auto& tri_edges = edges.triangle_edges[static_cast<std::size_t>(t)];
      for (std::size_t i = 0; i < 3; ++i) {
        if (tri_edges[i] == static_cast<int>(e)) {
          entries.emplace_back(split, triangles[static_cast<std::size_t>(t)][(i + 2) % 3],
                               1.0 / 8.0);
        }
      }
    }
  }
  out.subdivision.resize(next_vertex, vertex_count);
  out.subdivision.setFromTriplets(entries.begin(), entries.end());

  for (std::size_t t = 0; t < triangles.size(); ++t) {
    if (!refined[t]) continue;
    const auto [a, b, c] = triangles[t];
    const auto& e = edges.triangle_edges[t];
    const int ab = out.edge_vertex[static_cast<std::size_t>(e[0])];
    const int bc = out.edge_vertex[static_cast<std::size_t>(e[1])];
    const int ca = out.edge_vertex[static_cast<std::size_t>(e[2])];
    out.children.push_back({a, ab, ca});
    out.children.push_back({ab, b, bc});
    out.children.push_back({ca, bc, c});
    out.children.push_back({ab, bc, ca});
  }
  return out;
}

}  // namespace maquette::deform
