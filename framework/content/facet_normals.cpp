#include "content/facet_normals.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <numeric>
#include <vector>

namespace maquette {
namespace {

using Normal = std::array<double, 3>;
constexpr uint32_t kUp = UINT32_MAX;  // a copy facing +z instead of a face's normal

// The unit normal of triangle `corners` (counter-clockwise), zero when it has no area.
Normal face_normal(const std::vector<float>& positions, const uint32_t* corners) {
  const float *a = &positions[3 * size_t(corners[0])], *b = &positions[3 * size_t(corners[1])],
              *c = &positions[3 * size_t(corners[2])];
  const Normal u{double(b[0]) - a[0], double(b[1]) - a[1], double(b[2]) - a[2]},
      w{double(c[0]) - a[0], double(c[1]) - a[1], double(c[2]) - a[2]};
  Normal n{u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
  const double length = std::hypot(n[0], n[1], n[2]);
  for (double& x : n) x = length > 0 ? x / length : 0;
  return n;
}

// One output vertex: the vertex it copies and the face whose normal it takes (or kUp).
struct Copy {
  uint32_t vertex, face;
};

}  // namespace

MeshObject with_facet_normals(const MeshObject& object) {
  const size_t vertices = object.positions.size() / 3, triangles = object.indices.size() / 3;
  const std::vector<uint32_t>& indices = object.indices;
  std::vector<Normal> normal(triangles);
  for (size_t t = 0; t < triangles; ++t) normal[t] = face_normal(object.positions, &indices[3 * t]);
  // The corners grouped by vertex, each vertex's in triangle order (a counting sort): vertex v's
  // are by_vertex[begin[v]] to by_vertex[begin[v + 1] - 1].
  std::vector<uint32_t> begin(vertices + 1, 0), by_vertex(3 * triangles);
  for (size_t c = 0; c < by_vertex.size(); ++c) ++begin[indices[c] + 1];
  std::partial_sum(begin.begin(), begin.end(), begin.begin());
  {
    std::vector<uint32_t> next(begin.begin(), begin.end() - 1);
    for (size_t c = 0; c < by_vertex.size(); ++c) by_vertex[next[indices[c]]++] = uint32_t(c);
  }
  // Per vertex, its orientations (the faces whose normals they are) in the order its corners
  // meet them, each corner taking the first within kFacetNormalTurnDeg of its face's normal.
  const double min_dot = std::cos(kFacetNormalTurnDeg * std::numbers::pi / 180);
  const auto orientation = [&](uint32_t face) {
    return face == kUp ? Normal{0, 0, 1} : normal[face];
  };
  MeshObject out;
  out.provenance = object.provenance;
  out.material = object.material;
  out.indices.resize(by_vertex.size());
  std::vector<Copy> copies;
  copies.reserve(by_vertex.size() + vertices);  // at most one per corner and per unused vertex
  std::vector<uint32_t> own;
  for (uint32_t v = 0; v < vertices; ++v) {
    own.clear();
    for (uint32_t i = begin[v]; i < begin[v + 1]; ++i) {
      const uint32_t c = by_vertex[i], face = c / 3;
      const Normal& n = normal[face];
      const bool degenerate = n[0] == 0 && n[1] == 0 && n[2] == 0;
      size_t o = 0;
      for (; o < own.size() && !degenerate; ++o) {
        const Normal m = orientation(own[o]);
        if (!(m[0] * n[0] + m[1] * n[1] + m[2] * n[2] < min_dot)) break;
      }
      if (o == own.size()) own.push_back(degenerate ? kUp : face);
      out.indices[c] = uint32_t(copies.size() + o);
    }
    if (own.empty()) own.push_back(kUp);  // no triangle uses v: one copy (the anchor stays first)
    for (const uint32_t face : own) copies.push_back({v, face});
  }
  const bool uvs = !object.uvs.empty();
  out.positions.resize(3 * copies.size());
  out.normals.resize(3 * copies.size());
  if (uvs) out.uvs.resize(2 * copies.size());
  for (size_t i = 0; i < copies.size(); ++i) {
    const Normal n = orientation(copies[i].face);
    for (size_t k = 0; k < 3; ++k) {
      out.positions[3 * i + k] = object.positions[3 * size_t(copies[i].vertex) + k];
      out.normals[3 * i + k] = float(n[k]);
    }
    if (uvs)
      for (size_t k = 0; k < 2; ++k)
        out.uvs[2 * i + k] = object.uvs[2 * size_t(copies[i].vertex) + k];
  }
  return out;
}

}  // namespace maquette
