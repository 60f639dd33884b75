#include "loop_edges.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace maquette::deform {
namespace {

std::string edge_name(int a, int b) {
  return "(" + std::to_string(a) + ", " + std::to_string(b) + ")";
}

}  // namespace

MeshEdges mesh_edges(std::span<const std::array<int, 3>> triangles, int vertex_count) {
  // Edges are found in buckets by their smaller vertex (at most a few edges each): linear time.
  std::vector<int> bucket_start(static_cast<std::size_t>(vertex_count) + 1, 0);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const auto& tri = triangles[t];
    for (int i = 0; i < 3; ++i) {
      const int a = tri[static_cast<std::size_t>(i)];
      const int b = tri[static_cast<std::size_t>((i + 1) % 3)];
      if (a < 0 || a >= vertex_count || a == b) {
        throw std::invalid_argument(
            "mesh: triangle " + std::to_string(t) + " has corner " + std::to_string(a) +
            " (vertices: " + std::to_string(vertex_count) + ", corners must be distinct)");
      }
      ++bucket_start[static_cast<std::size_t>(std::min(a, b)) + 1];
    }
  }
  for (std::size_t v = 0; v < static_cast<std::size_t>(vertex_count); ++v) {
    bucket_start[v + 1] += bucket_start[v];
  }
  std::vector<int> bucket(static_cast<std::size_t>(bucket_start.back()));
  std::vector<int> bucket_size(static_cast<std::size_t>(vertex_count), 0);

  MeshEdges edges;
  edges.triangle_edges.resize(triangles.size());
  edges.vertices.reserve(triangles.size() * 3 / 2 + 2);
  edges.triangles.reserve(triangles.size() * 3 / 2 + 2);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (std::size_t i = 0; i < 3; ++i) {
      const int a = triangles[t][i];
      const int b = triangles[t][(i + 1) % 3];
      const auto low = static_cast<std::size_t>(std::min(a, b));
      const int* first = bucket.data() + bucket_start[low];
      const int* last = first + bucket_size[low];
      const int high = std::max(a, b);
      const int* found = std::find_if(first, last, [&](int e) {
        const auto& ends = edges.vertices[static_cast<std::size_t>(e)];
        return std::max(ends[0], ends[1]) == high;
      });
      int e;
      if (found == last) {
        e = static_cast<int>(edges.vertices.size());
        edges.vertices.push_back({a, b});
        edges.triangles.push_back({static_cast<int>(t), -1});
        bucket[static_cast<std::size_t>(bucket_start[low] + bucket_size[low]++)] = e;
      } else {
        e = *found;
        auto& sides = edges.triangles[static_cast<std::size_t>(e)];
        if (sides[1] >= 0) {
          throw std::invalid_argument("mesh: edge " + edge_name(a, b) + " is in triangles " +
                                      std::to_string(sides[0]) + ", " + std::to_string(sides[1]) +
                                      " and " + std::to_string(t) + " (not a 2-manifold)");
        }
        if (edges.vertices[static_cast<std::size_t>(e)][0] == a) {
          throw std::invalid_argument("mesh: triangles " + std::to_string(sides[0]) + " and " +
                                      std::to_string(t) + " run along edge " + edge_name(a, b) +
                                      " in the same direction (inconsistent orientation)");
        }
        sides[1] = static_cast<int>(t);
      }
      edges.triangle_edges[t][i] = e;
    }
  }
  return edges;
}

}  // namespace maquette::deform
