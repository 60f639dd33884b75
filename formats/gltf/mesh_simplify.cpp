#include "gltf/mesh_simplify.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "content/closed_solid.h"
#include "content/enu_transform.h"
#include "content/facet_normals.h"
#include "core/error.h"

namespace maquette {
namespace {

std::string image_extension(const std::string& mime, const std::string& where) {
  if (mime == "image/jpeg") return ".jpg";
  if (mime == "image/png") return ".png";
  if (mime == "image/webp") return ".webp";
  throw Error(where + ": cannot halve an image of type '" + mime + "'");
}

// The object in the parent's frame, all its vertices kept.
MeshObject reframed(const MeshObject& o, const EnuTransform& to_parent) {
  MeshObject out = o;
  for (size_t v = 0; v + 2 < o.positions.size(); v += 3) {
    const auto p = to_parent.point(o.positions[v], o.positions[v + 1], o.positions[v + 2]);
    for (int k = 0; k < 3; ++k) out.positions[v + k] = float(p[k]);
  }
  for (size_t v = 0; v + 2 < o.normals.size(); v += 3) {
    const auto n = to_parent.direction(o.normals[v], o.normals[v + 1], o.normals[v + 2]);
    const double length = std::hypot(n[0], n[1], n[2]);
    for (int k = 0; k < 3; ++k) out.normals[v + k] = float(length > 0 ? n[k] / length : n[k]);
  }
  return out;
}

double bbox_diagonal(const std::vector<float>& positions) {
  std::array<float, 3> lo, hi;
  lo.fill(std::numeric_limits<float>::infinity());
  hi.fill(-std::numeric_limits<float>::infinity());
  for (size_t v = 0; v < positions.size(); ++v) {
    lo[v % 3] = std::min(lo[v % 3], positions[v]);
    hi[v % 3] = std::max(hi[v % 3], positions[v]);
  }
  if (positions.empty()) return 0;
  return std::hypot(double(hi[0]) - lo[0], double(hi[1]) - lo[1], double(hi[2]) - lo[2]);
}

// `o` with the triangles `indices` (into its vertices) only, its vertices renumbered in the
// order they are first used.
MeshObject with_triangles(const MeshObject& o, const std::vector<uint32_t>& indices) {
  MeshObject out;
  out.provenance = o.provenance;
  out.material = o.material;
  std::vector<uint32_t> remap(o.positions.size() / 3, UINT32_MAX);
  for (uint32_t old : indices) {
    if (remap[old] == UINT32_MAX) {
      remap[old] = uint32_t(out.positions.size() / 3);
      const auto copy = [old](const std::vector<float>& from, std::vector<float>& to, int n) {
        if (!from.empty()) to.insert(to.end(), &from[n * old], &from[n * old + n]);
      };
      copy(o.positions, out.positions, 3);
      copy(o.normals, out.normals, 3);
      copy(o.uvs, out.uvs, 2);
    }
    out.indices.push_back(remap[old]);
  }
  return out;
}

MeshObject simplified_once(const MeshObject& o, double max_error_m) {
  const size_t vertices = o.positions.size() / 3;
  const float scale = meshopt_simplifyScale(o.positions.data(), vertices, 3 * sizeof(float));
  // A quarter of the triangles, but not below 4 (a tetrahedron): an object larger than the
  // sample does not vanish.
  const size_t target = std::max(o.indices.size() / 12 * 3, std::min<size_t>(12, o.indices.size()));
  std::vector<uint32_t> indices(o.indices.size());
  const float relative_error = scale > 0 ? float(max_error_m / scale) : 0.f;
  float achieved = 0;
  indices.resize(meshopt_simplify(indices.data(), o.indices.data(), o.indices.size(),
                                  o.positions.data(), vertices, 3 * sizeof(float), target,
                                  relative_error, 0, &achieved));
  return with_triangles(o, indices);
}

// Whether `o` is drawn with flat faces (content/facet_normals.h: buildings, bridge decks, prisms,
// lakes): every corner of a triangle carries its face's normal, within twice the turn under
// which with_facet_normals lets faces share a vertex. Triangles under 10 cm high are not asked:
// the store's GLB rounds positions to 1 mm, which turns their faces by more (slivers take a
// neighbour's normal).
bool has_facet_normals(const MeshObject& o) {
  if (o.normals.size() != o.positions.size()) return false;
  const double tolerance = std::cos(2 * kFacetNormalTurnDeg * M_PI / 180);
  const auto at = [](const std::vector<float>& values, uint32_t v) {
    return std::array<double, 3>{values[3 * v], values[3 * v + 1], values[3 * v + 2]};
  };
  for (size_t t = 0; t + 2 < o.indices.size(); t += 3) {
    const auto p = at(o.positions, o.indices[t]), q = at(o.positions, o.indices[t + 1]),
               r = at(o.positions, o.indices[t + 2]);
    const std::array<double, 3> a{q[0] - p[0], q[1] - p[1], q[2] - p[2]},
        b{r[0] - p[0], r[1] - p[1], r[2] - p[2]},
        n{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    const double area2 = std::hypot(n[0], n[1], n[2]);
    const double longest2 =
        std::max({a[0] * a[0] + a[1] * a[1] + a[2] * a[2], b[0] * b[0] + b[1] * b[1] + b[2] * b[2],
                  (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                      (a[2] - b[2]) * (a[2] - b[2])});
    if (area2 < 0.1 * std::sqrt(longest2)) continue;  // under 10 cm high
    for (int k = 0; k < 3; ++k) {
      const auto m = at(o.normals, o.indices[t + size_t(k)]);
      if ((m[0] * n[0] + m[1] * n[1] + m[2] * n[2]) <
          tolerance * area2 * std::hypot(m[0], m[1], m[2]))
        return false;
    }
  }
  return true;
}

// `o` with its vertices at one position (and texture coordinate) merged, without normals.
// Facet normals split each corner into one vertex per face meeting there: edge collapses, which
// never merge vertices, would find every face an island with a border and could hardly
// simplify a building.
MeshObject welded(const MeshObject& o) {
  const size_t vertices = o.positions.size() / 3;
  std::vector<meshopt_Stream> streams = {
      {o.positions.data(), 3 * sizeof(float), 3 * sizeof(float)}};
  if (!o.uvs.empty()) streams.push_back({o.uvs.data(), 2 * sizeof(float), 2 * sizeof(float)});
  std::vector<unsigned int> remap(vertices);
  const size_t unique = meshopt_generateVertexRemapMulti(
      remap.data(), o.indices.data(), o.indices.size(), vertices, streams.data(), streams.size());
  MeshObject out;
  out.provenance = o.provenance;
  out.material = o.material;
  out.indices.resize(o.indices.size());
  meshopt_remapIndexBuffer(out.indices.data(), o.indices.data(), o.indices.size(), remap.data());
  out.positions.resize(3 * unique);
  meshopt_remapVertexBuffer(out.positions.data(), o.positions.data(), vertices, 3 * sizeof(float),
                            remap.data());
  if (!o.uvs.empty()) {
    out.uvs.resize(2 * unique);
    meshopt_remapVertexBuffer(out.uvs.data(), o.uvs.data(), vertices, 2 * sizeof(float),
                              remap.data());
  }
  return out;
}

// Edge collapses within the bound can fold a solid (a wall of a building lower than the bound
// collapsed onto its roof leaves roof triangles without walls, or pushed through other ones:
// holes and inside-out triangles seen from afar): a closed, outward solid is simplified within
// ever smaller bounds until it stays one with no crossing triangles, and kept whole when none
// does.
constexpr int kSolidAttempts = 4;  // bounds of 1, 1/2, 1/4 and 1/8 of the first
// The first bound of a solid with facet normals, as a power of two of the level's: such solids
// are structures (buildings, decks), and a corner collapsed within the level's bound cuts a
// footprint, the ground showing through where the roof was (the campus example seen from 2 km
// in CesiumJS: 7.1 % of the roofs' pixels bare terrain at the level's bound, none at a quarter).
constexpr int kFacetSolidBoundExponent = -2;

MeshObject simplified(const MeshObject& o, double max_error_m) {
  if (!is_closed_outward(o)) return simplified_once(o, max_error_m);
  // A solid with facet normals is simplified welded (its split corners merged), its facet
  // normals made again for the faces it is left with; smooth normals are kept as they are.
  const bool facets = has_facet_normals(o);
  const MeshObject base = facets ? welded(o) : o;
  const int first = facets ? kFacetSolidBoundExponent : 0;
  for (int attempt = 0; attempt < kSolidAttempts; ++attempt) {
    MeshObject s = simplified_once(base, std::ldexp(max_error_m, first - attempt));
    s = with_triangles(s, without_fins(s));
    if (is_closed_outward(s) && !has_crossing_triangles(s))
      return facets ? with_facet_normals(s) : s;
  }
  return o;
}

}  // namespace

std::string halve_image(const std::string& image, const std::string& mime,
                        const std::string& where) {
  const std::string extension = image_extension(mime, where);
  const cv::Mat bytes(1, int(image.size()), CV_8U, const_cast<char*>(image.data()));
  const cv::Mat decoded = cv::imdecode(bytes, cv::IMREAD_UNCHANGED);
  if (decoded.empty()) throw Error(where + ": the " + mime + " image does not decode");
  cv::Mat half;
  cv::resize(decoded, half, cv::Size(std::max(1, decoded.cols / 2), std::max(1, decoded.rows / 2)),
             0, 0, cv::INTER_AREA);
  std::vector<uchar> out;
  if (!cv::imencode(extension, half, out))
    throw Error(where + ": cannot encode the halved " + mime + " image");
  return {reinterpret_cast<const char*>(out.data()), out.size()};
}

MeshContent simplify_mesh_children(std::span<const MeshContent> children,
                                   const ContentLevel& level) {
  MeshContent out;
  out.origin = level.origin;
  std::vector<Material> originals;  // out.materials before their images are halved
  for (const MeshContent& child : children) {
    const EnuTransform to_parent(child.origin, level.origin);
    std::vector<int> material(child.materials.size());
    for (size_t m = 0; m < child.materials.size(); ++m) {
      const auto it = std::find(originals.begin(), originals.end(), child.materials[m]);
      material[m] = int(it - originals.begin());
      if (it == originals.end()) originals.push_back(child.materials[m]);
    }
    for (const MeshObject& object : child.objects) {
      MeshObject o = reframed(object, to_parent);
      if (bbox_diagonal(o.positions) < level.sample_m) continue;
      o = simplified(o, level.sample_m / 2);
      if (o.indices.empty()) continue;
      if (o.material >= 0) o.material = material[size_t(o.material)];
      out.objects.push_back(std::move(o));
    }
  }
  // Only the materials of objects kept, in their order.
  std::vector<int> kept(originals.size(), -1);
  for (MeshObject& o : out.objects) {
    if (o.material < 0) continue;
    int& index = kept[size_t(o.material)];
    if (index < 0) {
      index = int(out.materials.size());
      out.materials.push_back(originals[size_t(o.material)]);
    }
    o.material = index;
  }
  for (Material& m : out.materials)
    if (!m.image.empty()) m.image = halve_image(m.image, m.image_mime, "material '" + m.name + "'");
  return out;
}

}  // namespace maquette
