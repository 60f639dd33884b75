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

// The edges at each even vertex (compressed lists by vertex: their counts are the valences) and
// how many of them are on the surface's border.
struct EvenVertexEdges {
  std::vector<int> first;
  std::vector<int> edges;
  std::vector<int> border_edges;
};

// A gap in an even vertex's fan (an edge with one triangle that is not on the surface's border)
// means its mask would miss neighbours: std::logic_error.
EvenVertexEdges even_vertex_edges(const MeshEdges& edges, const std::vector<bool>& on_border,
                                  const std::vector<bool>& even) {
  EvenVertexEdges out;
  out.first.assign(even.size() + 1, 0);
  out.border_edges.assign(even.size(), 0);
  for (std::size_t e = 0; e < edges.vertices.size(); ++e) {
    for (const int v : edges.vertices[e]) {
      const auto vi = static_cast<std::size_t>(v);
      if (!even[vi]) continue;
      ++out.first[vi + 1];
      if (on_border[e]) {
        ++out.border_edges[vi];
      } else if (edges.triangles[e][1] < 0) {
        throw std::logic_error("Loop refinement: vertex " + std::to_string(v) +
                               " of a refined triangle lacks triangles around it");
      }
    }
  }
  for (std::size_t v = 0; v < even.size(); ++v) out.first[v + 1] += out.first[v];
  out.edges.resize(static_cast<std::size_t>(out.first.back()));
  std::vector<int> cursor(out.first.begin(), out.first.end() - 1);
  for (std::size_t e = 0; e < edges.vertices.size(); ++e) {
    for (const int v : edges.vertices[e]) {
      const auto vi = static_cast<std::size_t>(v);
      if (even[vi]) out.edges[static_cast<std::size_t>(cursor[vi]++)] = static_cast<int>(e);
    }
  }
  return out;
}

// Writes a row-major matrix row after row, each sorted by column, straight into its compressed
// arrays (no triplet list, no transposition).
class RowWriter {
 public:
  RowWriter(SubdivisionMatrix& matrix, int rows, int columns, std::size_t capacity)
      : matrix_(matrix) {
    matrix_.resize(rows, columns);
    matrix_.resizeNonZeros(static_cast<Eigen::Index>(capacity));
    matrix_.outerIndexPtr()[0] = 0;
  }
  void add(int column, double weight) { row_.emplace_back(column, weight); }
  void end_row() {
    std::sort(row_.begin(), row_.end());
    for (std::size_t i = 0; i < row_.size(); ++i) {
      if (i > 0 && row_[i].first == row_[i - 1].first) {
        matrix_.valuePtr()[written_ - 1] +=
            row_[i].second;  // an edge's opposite corners may coincide
        continue;
      }
      matrix_.innerIndexPtr()[written_] = row_[i].first;
      matrix_.valuePtr()[written_++] = row_[i].second;
    }
    matrix_.outerIndexPtr()[++rows_] = written_;
    row_.clear();
  }
  void finish() { matrix_.resizeNonZeros(written_); }

 private:
  SubdivisionMatrix& matrix_;
  std::vector<std::pair<int, double>> row_;
  int rows_ = 0;
  int written_ = 0;
};

// A vertex's row: Loop's vertex mask for an even vertex, else the identity.
void write_vertex_row(RowWriter& writer, const MeshEdges& edges, const std::vector<bool>& on_border,
                      const EvenVertexEdges& around, bool even, int v) {
  const auto vi = static_cast<std::size_t>(v);
  const std::span<const int> incident(around.edges.data() + around.first[vi],
                                      around.edges.data() + around.first[vi + 1]);
  const auto other_end = [&](int e) {
    const auto& ends = edges.vertices[static_cast<std::size_t>(e)];
    return ends[0] == v ? ends[1] : ends[0];
  };
  if (!even) {
    writer.add(v, 1.0);
  } else if (around.border_edges[vi] == 0) {
    const auto valence = static_cast<int>(incident.size());
    const double weight = inner_neighbour_weight(valence);
    writer.add(v, 1.0 - valence * weight);
    for (const int e : incident) writer.add(other_end(e), weight);
  } else if (around.border_edges[vi] == 2) {
    writer.add(v, 3.0 / 4.0);
    for (const int e : incident) {
      if (on_border[static_cast<std::size_t>(e)]) writer.add(other_end(e), 1.0 / 8.0);
    }
  } else {
    throw std::invalid_argument("mesh: vertex " + std::to_string(v) + " has " +
                                std::to_string(around.border_edges[vi]) +
                                " border edges (a border vertex needs exactly 2)");
  }
  writer.end_row();
}

// The row of the new vertex on edge e: Loop's edge mask.
void write_edge_row(RowWriter& writer, std::span<const std::array<int, 3>> triangles,
                    const MeshEdges& edges, const std::vector<bool>& on_border, std::size_t e) {
  const auto [a, b] = edges.vertices[e];
  if (on_border[e]) {
    writer.add(a, 0.5);
    writer.add(b, 0.5);
  } else {
    writer.add(a, 3.0 / 8.0);
    writer.add(b, 3.0 / 8.0);
    for (const int t : edges.triangles[e]) {
      const auto& triangle_edges = edges.triangle_edges[static_cast<std::size_t>(t)];
      for (std::size_t i = 0; i < 3; ++i) {
        if (triangle_edges[i] == static_cast<int>(e)) {
          writer.add(triangles[static_cast<std::size_t>(t)][(i + 2) % 3], 1.0 / 8.0);
        }
      }
    }
  }
  writer.end_row();
}

}  // namespace

LoopRefinement refine_loop(std::span<const std::array<int, 3>> triangles, const MeshEdges& edges,
                           const std::vector<bool>& on_border, const std::vector<bool>& refined,
                           int vertex_count) {
  std::vector<bool> even(static_cast<std::size_t>(vertex_count), false);
  LoopRefinement out;
  out.edge_vertex.assign(edges.vertices.size(), -1);
  std::vector<int> split_edges;  // per new vertex
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    if (!refined[t]) continue;
    for (std::size_t i = 0; i < 3; ++i) {
      even[static_cast<std::size_t>(triangles[t][i])] = true;
      const int e = edges.triangle_edges[t][i];
      int& split = out.edge_vertex[static_cast<std::size_t>(e)];
      if (split < 0) {
        split = vertex_count + static_cast<int>(split_edges.size());
        split_edges.push_back(e);
        out.new_vertex_ends.push_back(edges.vertices[static_cast<std::size_t>(e)]);
      }
    }
  }

  const EvenVertexEdges around = even_vertex_edges(edges, on_border, even);
  RowWriter writer(out.subdivision, vertex_count + static_cast<int>(split_edges.size()),
                   vertex_count, even.size() + around.edges.size() + 4 * split_edges.size());
  for (int v = 0; v < vertex_count; ++v) {
    write_vertex_row(writer, edges, on_border, around, even[static_cast<std::size_t>(v)], v);
  }
  for (const int e : split_edges) {
    write_edge_row(writer, triangles, edges, on_border, static_cast<std::size_t>(e));
  }
  writer.finish();

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
