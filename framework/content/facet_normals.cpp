#include "content/facet_normals.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace maquette {

MeshObject with_facet_normals(const MeshObject& object) {
  const size_t vertices = object.positions.size() / 3, triangles = object.indices.size() / 3;
  const auto position = [&](uint32_t v) {
    return std::array<double, 3>{object.positions[3 * v], object.positions[3 * v + 1],
                                 object.positions[3 * v + 2]};
  };
  std::vector<std::array<double, 3>> face_normal(triangles);
  for (size_t t = 0; t < triangles; ++t) {
    const auto a = position(object.indices[3 * t]), b = position(object.indices[3 * t + 1]),
               c = position(object.indices[3 * t + 2]);
    const std::array<double, 3> u{b[0] - a[0], b[1] - a[1], b[2] - a[2]},
        w{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    std::array<double, 3> n{u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
                            u[0] * w[1] - u[1] * w[0]};
    const double length = std::hypot(n[0], n[1], n[2]);
    for (double& x : n) x = length > 0 ? x / length : 0;
    face_normal[t] = n;
  }
  // Per vertex, its orientations in the order met; per triangle corner, which one it takes.
  const double min_dot = std::cos(kFacetNormalTurnDeg * std::numbers::pi / 180);
  std::vector<std::vector<std::array<double, 3>>> orientations(vertices);
  std::vector<uint32_t> corner_orientation(object.indices.size());
  for (size_t t = 0; t < triangles; ++t)
    for (size_t k = 0; k < 3; ++k) {
      std::vector<std::array<double, 3>>& own = orientations[object.indices[3 * t + k]];
      const std::array<double, 3>& n = face_normal[t];
      const bool degenerate = n[0] == 0 && n[1] == 0 && n[2] == 0;
      size_t o = 0;
      while (o < own.size() && !degenerate &&
             own[o][0] * n[0] + own[o][1] * n[1] + own[o][2] * n[2] < min_dot)
        ++o;
      if (o == own.size()) own.push_back(degenerate ? std::array<double, 3>{0, 0, 1} : n);
      corner_orientation[3 * t + k] = uint32_t(std::min(o, own.size() - 1));
    }
  // The copies in the order of the vertices they come from (an object's first vertex, its
  // anchor, stays first).
  MeshObject out;
  out.provenance = object.provenance;
  out.material = object.material;
  std::vector<uint32_t> first_copy(vertices);
  for (uint32_t v = 0; v < vertices; ++v) {
    first_copy[v] = uint32_t(out.positions.size() / 3);
    for (const std::array<double, 3>& n : orientations[v]) {
      out.positions.insert(out.positions.end(), object.positions.begin() + 3 * v,
                           object.positions.begin() + 3 * v + 3);
      if (!object.uvs.empty())
        out.uvs.insert(out.uvs.end(), object.uvs.begin() + 2 * v, object.uvs.begin() + 2 * v + 2);
      out.normals.insert(out.normals.end(), {float(n[0]), float(n[1]), float(n[2])});
    }
  }
  out.indices.reserve(object.indices.size());
  for (size_t c = 0; c < object.indices.size(); ++c)
    out.indices.push_back(first_copy[object.indices[c]] + corner_orientation[c]);
  return out;
}

}  // namespace maquette
