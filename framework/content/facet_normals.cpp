#include "content/facet_normals.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

namespace maquette {
namespace {

constexpr uint32_t kNone = UINT32_MAX;
constexpr std::array<double, 3> kUp{0, 0, 1};

// One orientation of a vertex, in one flat pool for all vertices (in the order met): its unit
// normal and the vertex's next orientation in the pool.
struct Orientation {
  std::array<double, 3> normal;
  uint32_t next = kNone;
};

// The unit normal of triangle `corners` (counter-clockwise), zero when it has no area.
std::array<double, 3> face_normal(const std::vector<float>& positions, const uint32_t* corners) {
  const float *a = &positions[3 * size_t(corners[0])], *b = &positions[3 * size_t(corners[1])],
              *c = &positions[3 * size_t(corners[2])];
  const std::array<double, 3> u{double(b[0]) - a[0], double(b[1]) - a[1], double(b[2]) - a[2]},
      w{double(c[0]) - a[0], double(c[1]) - a[1], double(c[2]) - a[2]};
  std::array<double, 3> n{u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
                          u[0] * w[1] - u[1] * w[0]};
  const double length = std::hypot(n[0], n[1], n[2]);
  for (double& x : n) x = length > 0 ? x / length : 0;
  return n;
}

}  // namespace

MeshObject with_facet_normals(const MeshObject& object) {
  const size_t vertices = object.positions.size() / 3, corners = object.indices.size();
  const double min_dot = std::cos(kFacetNormalTurnDeg * std::numbers::pi / 180);
  // Per vertex its first orientation in the pool; per corner the orientation it takes (kept in
  // the output's indices until the copies are numbered).
  std::vector<uint32_t> first(vertices, kNone);
  std::vector<Orientation> pool;
  pool.reserve(vertices + vertices / 2);
  MeshObject out;
  out.provenance = object.provenance;
  out.material = object.material;
  out.indices.resize(corners);
  for (size_t t = 0; t + 2 < corners; t += 3) {
    const std::array<double, 3> n = face_normal(object.positions, &object.indices[t]);
    const bool degenerate = n[0] == 0 && n[1] == 0 && n[2] == 0;
    for (size_t c = t; c < t + 3; ++c) {
      uint32_t* link = &first[object.indices[c]];
      while (*link != kNone && !degenerate) {
        const std::array<double, 3>& o = pool[*link].normal;
        if (!(o[0] * n[0] + o[1] * n[1] + o[2] * n[2] < min_dot)) break;
        link = &pool[*link].next;
      }
      uint32_t taken = *link;
      if (taken == kNone) {  // `link` may be in the pool, which push_back may move
        taken = *link = uint32_t(pool.size());
        pool.push_back({degenerate ? kUp : n});
      }
      out.indices[c] = taken;
    }
  }
  // A vertex no triangle uses keeps one copy (the anchor stays first).
  for (uint32_t& f : first)
    if (f == kNone) {
      f = uint32_t(pool.size());
      pool.push_back({kUp});
    }
  // The copies in the order of the vertices they come from, each vertex's in the order met.
  const bool uvs = !object.uvs.empty();
  out.positions.resize(3 * pool.size());
  out.normals.resize(3 * pool.size());
  if (uvs) out.uvs.resize(2 * pool.size());
  std::vector<uint32_t> copy_of(pool.size());
  uint32_t copy = 0;
  for (size_t v = 0; v < vertices; ++v)
    for (uint32_t o = first[v]; o != kNone; o = pool[o].next, ++copy) {
      copy_of[o] = copy;
      for (size_t k = 0; k < 3; ++k) {
        out.positions[3 * size_t(copy) + k] = object.positions[3 * v + k];
        out.normals[3 * size_t(copy) + k] = float(pool[o].normal[k]);
      }
      if (uvs)
        for (size_t k = 0; k < 2; ++k) out.uvs[2 * size_t(copy) + k] = object.uvs[2 * v + k];
    }
  for (uint32_t& index : out.indices) index = copy_of[index];
  return out;
}

}  // namespace maquette
