#include "loop_refine.h"

#include <algorithm>
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
  std::vector<int> split_edges;  // per new vertex
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    if (!refined[t]) continue;
    for (std::size_t i = 0; i < 3; ++i) {
      even[static_cast<std::size_t>(triangles[t][i])] = true;
      const int split_edge_index = edges.triangle_edges[t][i];
      int& split = out.edge_vertex[static_cast<std::size_t>(split_edge_index)];
      if (split < 0) {
        split = next_vertex++;
        split_edges.push_back(split_edge_index);
        out.new_vertex_ends.push_back(edges.vertices[static_cast<std::size_t>(split_edge_index)]);
      }
    }
  }

  // The edges at each even vertex (compressed lists, by vertex: their counts are the valences)
  // and its border edges; a gap in a vertex's fan (an edge with one triangle that is not on the
  // surface's border) means its mask would miss neighbours.
  std::vector<int> first_incident(vertices + 1, 0);
  std::vector<int> border_edges(vertices, 0);
  for (std::size_t e = 0; e < edges.vertices.size(); ++e) {
    for (const int v : edges.vertices[e]) {
      const auto vi = static_cast<std::size_t>(v);
      if (!even[vi]) continue;
      ++first_incident[vi + 1];
      if (on_border[e]) {
        ++border_edges[vi];
      } else if (edges.triangles[e][1] < 0) {
        throw std::logic_error("Loop refinement: vertex " + std::to_string(v) +
                               " of a refined triangle lacks triangles around it");
      }
    }
  }

  for (std::size_t v = 0; v < vertices; ++v) first_incident[v + 1] += first_incident[v];
  std::vector<int> incident(static_cast<std::size_t>(first_incident.back()));
  {
    std::vector<int> cursor(first_incident.begin(), first_incident.end() - 1);
    for (std::size_t e = 0; e < edges.vertices.size(); ++e) {
      for (const int v : edges.vertices[e]) {
        const auto vi = static_cast<std::size_t>(v);
        if (even[vi]) incident[static_cast<std::size_t>(cursor[vi]++)] = static_cast<int>(e);
      }
    }
  }

  // Rows in order, each sorted by column, written straight into the compressed matrix.
  out.subdivision.resize(next_vertex, vertex_count);
  out.subdivision.resizeNonZeros(static_cast<Eigen::Index>(
      vertices + incident.size() + 4 * (static_cast<std::size_t>(next_vertex) - vertices)));
  int* const outer = out.subdivision.outerIndexPtr();
  int* const inner = out.subdivision.innerIndexPtr();
  double* const value = out.subdivision.valuePtr();
  int written = 0;
  std::vector<std::pair<int, double>> row;
  const auto write_row = [&](int r) {
    std::sort(row.begin(), row.end());
    for (std::size_t i = 0; i < row.size(); ++i) {
      if (i > 0 && row[i].first == row[i - 1].first) {
        value[written - 1] += row[i].second;  // an edge's two opposite corners may coincide
        continue;
      }
      inner[written] = row[i].first;
      value[written++] = row[i].second;
    }
    outer[r + 1] = written;
    row.clear();
  };
  outer[0] = 0;
  for (std::size_t v = 0; v < vertices; ++v) {
    const int vi = static_cast<int>(v);
    const std::span<const int> around(incident.data() + first_incident[v],
                                      incident.data() + first_incident[v + 1]);
    const auto other_end = [&](int e) {
      const auto& ends = edges.vertices[static_cast<std::size_t>(e)];
      return ends[0] == vi ? ends[1] : ends[0];
    };
    if (!even[v]) {
      row.emplace_back(vi, 1.0);
    } else if (border_edges[v] == 0) {
      const auto valence = static_cast<int>(around.size());
      const double weight = inner_neighbour_weight(valence);
      row.emplace_back(vi, 1.0 - valence * weight);
      for (const int e : around) row.emplace_back(other_end(e), weight);
    } else if (border_edges[v] == 2) {
      row.emplace_back(vi, 3.0 / 4.0);
      for (const int e : around) {
        if (on_border[static_cast<std::size_t>(e)]) row.emplace_back(other_end(e), 1.0 / 8.0);
      }
    } else {
      throw std::invalid_argument("mesh: vertex " + std::to_string(v) + " has " +
                                  std::to_string(border_edges[v]) +
                                  " border edges (a border vertex needs exactly 2)");
    }
    write_row(vi);
  }
  for (int split = vertex_count; split < next_vertex; ++split) {
    const auto e =
        static_cast<std::size_t>(split_edges[static_cast<std::size_t>(split - vertex_count)]);
    const auto [a, b] = edges.vertices[e];
    if (on_border[e]) {
      row.emplace_back(a, 0.5);
      row.emplace_back(b, 0.5);
    } else {
      row.emplace_back(a, 3.0 / 8.0);
      row.emplace_back(b, 3.0 / 8.0);
      for (const int t : edges.triangles[e]) {
        const auto& tri_edges = edges.triangle_edges[static_cast<std::size_t>(t)];
        for (std::size_t i = 0; i < 3; ++i) {
          if (tri_edges[i] == static_cast<int>(e)) {
            row.emplace_back(triangles[static_cast<std::size_t>(t)][(i + 2) % 3], 1.0 / 8.0);
          }
        }
      }
    }
    write_row(split);
  }
  out.subdivision.resizeNonZeros(written);

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
