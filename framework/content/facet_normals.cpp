#include "content/facet_normals.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <numeric>
#include <vector>

#include "core/parallel_chunks.h"

namespace maquette {
namespace {

using Normal = std::array<double, 3>;
constexpr Normal kUpNormal{0, 0, 1};  // a degenerate triangle's or unused vertex's copy

// The unit normal of triangle `corners` (counter-clockwise), zero when it is a sliver: lower
// than kFacetMinHeightM over its longest side.
Normal face_normal(const std::vector<float>& positions, const uint32_t* corners) {
  const float *a = &positions[3 * size_t(corners[0])], *b = &positions[3 * size_t(corners[1])],
              *c = &positions[3 * size_t(corners[2])];
  const Normal u{double(b[0]) - a[0], double(b[1]) - a[1], double(b[2]) - a[2]},
      w{double(c[0]) - a[0], double(c[1]) - a[1], double(c[2]) - a[2]};
  Normal n{u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
  const double length = std::hypot(n[0], n[1], n[2]);  // twice the area
  const auto squared = [](const Normal& v) { return v[0] * v[0] + v[1] * v[1] + v[2] * v[2]; };
  const double longest = std::sqrt(
      std::max({squared(u), squared(w), squared({w[0] - u[0], w[1] - u[1], w[2] - u[2]})}));
  const bool sliver = !(length > kFacetMinHeightM * longest);
  for (double& x : n) x = sliver ? 0 : x / length;
  return n;
}

bool degenerate(const Normal& n) { return n[0] == 0 && n[1] == 0 && n[2] == 0; }

// Triangles or vertices per parallel chunk: a building's few are done in one call, without TBB.
constexpr size_t kChunk = 4096;

}  // namespace

MeshObject with_facet_normals(const MeshObject& object) {
  const size_t vertices = object.positions.size() / 3, triangles = object.indices.size() / 3;
  const std::vector<uint32_t>& indices = object.indices;
  std::vector<Normal> normal(triangles);
  parallel_chunks(triangles, kChunk, [&](size_t first, size_t last) {
    for (size_t t = first; t < last; ++t)
      normal[t] = face_normal(object.positions, &indices[3 * t]);
  });
  // The corners grouped by vertex, each vertex's in triangle order (a counting sort): vertex v's
  // are by_vertex[begin[v]] to by_vertex[begin[v + 1] - 1].
  std::vector<uint32_t> begin(vertices + 1, 0), by_vertex(3 * triangles);
  for (size_t c = 0; c < by_vertex.size(); ++c) ++begin[indices[c] + 1];
  std::partial_sum(begin.begin(), begin.end(), begin.begin());
  {
    std::vector<uint32_t> next(begin.begin(), begin.end() - 1);
    for (size_t c = 0; c < by_vertex.size(); ++c) by_vertex[next[indices[c]]++] = uint32_t(c);
  }
  // Per vertex, its orientations in the order its corners meet them, each corner taking the
  // first within kFacetNormalTurnDeg of its face's normal, a degenerate corner the first of them
  // (wherever it comes: a sliver met first would otherwise make a copy of its vertex of its own,
  // facing up, that no other face shares): out.indices first holds each corner's orientation
  // among its vertex's, copies[v] their count (vertices in parallel).
  const double min_dot = std::cos(kFacetNormalTurnDeg * std::numbers::pi / 180);
  MeshObject out;
  out.provenance = object.provenance;
  out.material = object.material;
  out.indices.resize(by_vertex.size());
  std::vector<uint32_t> copies(vertices + 1, 0);
  parallel_chunks(vertices, kChunk, [&](size_t first, size_t last) {
    std::vector<const Normal*> own;
    for (uint32_t v = uint32_t(first); v < last; ++v) {
      own.clear();
      for (uint32_t i = begin[v]; i < begin[v + 1]; ++i) {
        const uint32_t c = by_vertex[i];
        const Normal& n = normal[c / 3];
        if (degenerate(n)) continue;
        size_t o = 0;
        for (; o < own.size(); ++o) {
          const Normal& m = *own[o];
          if (!(m[0] * n[0] + m[1] * n[1] + m[2] * n[2] < min_dot)) break;
        }
        if (o == own.size()) own.push_back(&n);
        out.indices[c] = uint32_t(o);
      }
      for (uint32_t i = begin[v]; i < begin[v + 1]; ++i) {
        const uint32_t c = by_vertex[i];
        if (!degenerate(normal[c / 3])) continue;
        if (own.empty()) own.push_back(&kUpNormal);
        out.indices[c] = 0;
      }
      copies[v + 1] = uint32_t(std::max<size_t>(own.size(), 1));  // an unused vertex: one copy
    }
  });
  std::partial_sum(copies.begin(), copies.end(), copies.begin());
  // The copies, each vertex's in the order of its orientations (the first of its corners that is
  // not degenerate gives its normal), written in parallel at their final places.
  const bool uvs = !object.uvs.empty();
  out.positions.resize(3 * size_t(copies.back()));
  out.normals.resize(out.positions.size());
  if (uvs) out.uvs.resize(2 * size_t(copies.back()));
  const auto copy = [&](uint32_t v, size_t to, const Normal& n) {
    for (size_t k = 0; k < 3; ++k) {
      out.positions[3 * to + k] = object.positions[3 * size_t(v) + k];
      out.normals[3 * to + k] = float(n[k]);
    }
    if (uvs)
      for (size_t k = 0; k < 2; ++k) out.uvs[2 * to + k] = object.uvs[2 * size_t(v) + k];
  };
  parallel_chunks(vertices, kChunk, [&](size_t first, size_t last) {
    for (uint32_t v = uint32_t(first); v < last; ++v) {
      uint32_t made = 0;
      for (uint32_t i = begin[v]; i < begin[v + 1]; ++i) {
        const uint32_t c = by_vertex[i], o = out.indices[c];
        if (o == made) {  // the corner that met this orientation first
          const Normal* n = &kUpNormal;
          for (uint32_t j = i; j < begin[v + 1] && n == &kUpNormal; ++j) {
            const uint32_t d = by_vertex[j];  // not renumbered yet (j >= i)
            if (out.indices[d] == o && !degenerate(normal[d / 3])) n = &normal[d / 3];
          }
          copy(v, copies[v] + made, *n);
          ++made;
        }
        out.indices[c] = copies[v] + o;
      }
      if (made == 0) copy(v, copies[v], kUpNormal);
    }
  });
  return out;
}

}  // namespace maquette
