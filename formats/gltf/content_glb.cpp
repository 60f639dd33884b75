#include "gltf/content_glb.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "gltf/glb_writer.h"
#include "gltf/lattice.h"

namespace maquette {
namespace {

constexpr double kRad = std::numbers::pi / 180;
constexpr double kEarthRadius = 6371008.8;

// Unit prototypes, base centred on the origin, y up: a box of side 1, a cone of diameter 1
// and height 1 (16 sides).
TerrainMesh prototype(const std::string& name) {
  TerrainMesh m;
  if (name == "box") {
    for (int i = 0; i < 8; ++i)
      m.positions.insert(m.positions.end(),
                         {i & 1 ? 0.5 : -0.5, i & 2 ? 1. : 0., i & 4 ? 0.5 : -0.5});
    m.indices = {0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2,
                 1, 3, 7, 1, 7, 5, 0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6};
    return m;
  }
  constexpr int kSides = 16;
  m.positions = {0, 1, 0, 0, 0, 0};  // apex, base centre
  for (int i = 0; i < kSides; ++i) {
    const double a = 2 * std::numbers::pi * i / kSides;
    m.positions.insert(m.positions.end(), {0.5 * std::cos(a), 0, -0.5 * std::sin(a)});
    const uint32_t v = 2 + uint32_t(i), w = 2 + uint32_t((i + 1) % kSides);
    m.indices.insert(m.indices.end(), {0, v, w, 1, w, v});
  }
  return m;
}

using Mat3 = std::array<Vec3, 3>;  // columns

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3 unit(const Vec3& a) {
  const double n = std::hypot(a[0], a[1], a[2]);
  return {a[0] / n, a[1] / n, a[2] / n};
}

// The rotation taking the prototype's axes (x east, y up, z south) to the instance's local axes
// in the export frame, after turning it by its heading (clockwise seen from above).
std::array<float, 4> instance_rotation(const LocalFrame& frame, const ContentInstance& i) {
  const Vec3 p = frame.to_gltf({i.lon, i.lat}, i.height);
  const Vec3 up = unit(sub(frame.to_gltf({i.lon, i.lat}, i.height + 1), p));
  const Vec3 south = unit(cross(sub(frame.to_gltf({i.lon + 1e-5, i.lat}, i.height), p), up));
  const Vec3 east = cross(up, south);
  const double c = std::cos(i.heading * kRad), s = std::sin(i.heading * kRad);
  // Clockwise by h seen from above: east -> cos h east + sin h south (east turns south),
  // south -> cos h south - sin h east.
  const Mat3 r = {
      Vec3{c * east[0] + s * south[0], c * east[1] + s * south[1], c * east[2] + s * south[2]}, up,
      Vec3{c * south[0] - s * east[0], c * south[1] - s * east[1], c * south[2] - s * east[2]}};
  auto m = [&r](int row, int col) { return r[size_t(col)][size_t(row)]; };
  // Matrix to quaternion (Shepperd's method, the largest of the four candidates).
  const double t = m(0, 0) + m(1, 1) + m(2, 2);
  std::array<double, 4> q;  // x, y, z, w
  if (t > 0) {
    const double k = 0.5 / std::sqrt(t + 1);
    q = {(m(2, 1) - m(1, 2)) * k, (m(0, 2) - m(2, 0)) * k, (m(1, 0) - m(0, 1)) * k, 0.25 / k};
  } else if (m(0, 0) > m(1, 1) && m(0, 0) > m(2, 2)) {
    const double k = 2 * std::sqrt(1 + m(0, 0) - m(1, 1) - m(2, 2));
    q = {0.25 * k, (m(0, 1) + m(1, 0)) / k, (m(0, 2) + m(2, 0)) / k, (m(2, 1) - m(1, 2)) / k};
  } else if (m(1, 1) > m(2, 2)) {
    const double k = 2 * std::sqrt(1 + m(1, 1) - m(0, 0) - m(2, 2));
    q = {(m(0, 1) + m(1, 0)) / k, 0.25 * k, (m(1, 2) + m(2, 1)) / k, (m(0, 2) - m(2, 0)) / k};
  } else {
    const double k = 2 * std::sqrt(1 + m(2, 2) - m(0, 0) - m(1, 1));
    q = {(m(0, 2) + m(2, 0)) / k, (m(1, 2) + m(2, 1)) / k, 0.25 * k, (m(1, 0) - m(0, 1)) / k};
  }
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  return {float(q[0] / n), float(q[1] / n), float(q[2] / n), float(q[3] / n)};
}

// Grows `r` to hold a point with a lateral margin of `radius` metres and `top` metres above it.
void extend(std::array<double, 6>& r, double lon, double lat, double height, double radius,
            double top) {
  const double dlat = radius / kEarthRadius;
  const double dlon = dlat / std::max(1e-6, std::cos(lat * kRad));
  r[0] = std::min(r[0], lon * kRad - dlon);
  r[1] = std::min(r[1], lat * kRad - dlat);
  r[2] = std::max(r[2], lon * kRad + dlon);
  r[3] = std::max(r[3], lat * kRad + dlat);
  r[4] = std::min(r[4], height);
  r[5] = std::max(r[5], height + top);
}

}  // namespace

ContentGlb content_glb(const ContentTile& content, const LocalFrame& frame,
                       const QuantizationBits& bits, bool draco, const std::string& name) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  ContentGlb out;
  out.region = {kInf, kInf, -kInf, -kInf, kInf, -kInf};
  TerrainMesh mesh;
  InstanceTransforms instances;
  if (content.kind == ContentTile::Kind::Mesh) {
    const auto& p = content.positions;
    for (size_t i = 0; i + 2 < p.size(); i += 3) {
      const Vec3 v = frame.to_gltf({p[i], p[i + 1]}, p[i + 2]);
      mesh.positions.insert(mesh.positions.end(), v.begin(), v.end());
      extend(out.region, p[i], p[i + 1], p[i + 2], 0, 0);
    }
    mesh.indices = content.indices;
  } else {
    mesh = prototype(content.prototype);
    // Instances are placed from the first one, the node's translation (the mesh's offset), so
    // that their float translations stay precise far from the export frame's origin.
    if (!content.instances.empty()) {
      const ContentInstance& first = content.instances.front();
      mesh.offset = frame.to_gltf({first.lon, first.lat}, first.height);
    }
    const double radius = content.prototype == "box" ? std::sqrt(0.5) : 0.5;
    for (const ContentInstance& i : content.instances) {
      const Vec3 t = frame.to_gltf({i.lon, i.lat}, i.height);
      const auto q = instance_rotation(frame, i);
      instances.translation.insert(instances.translation.end(),
                                   {float(t[0] - mesh.offset[0]), float(t[1] - mesh.offset[1]),
                                    float(t[2] - mesh.offset[2])});
      instances.rotation.insert(instances.rotation.end(), q.begin(), q.end());
      instances.scale.insert(instances.scale.end(),
                             {float(i.scale), float(i.scale), float(i.scale)});
      extend(out.region, i.lon, i.lat, i.height, radius * i.scale, i.scale);
    }
  }
  DracoPrimitive compressed;
  if (content.kind == ContentTile::Kind::Mesh) {  // measured from an offset at the mesh
    const Lattice lattice = Lattice::for_extent(extent(mesh.positions), bits.position);
    lattice.rebase(mesh);
    if (draco) compressed = encode_draco(mesh, lattice, bits);
  }
  GlbPrimitive prim{&mesh,         compressed.data.empty() ? nullptr : &compressed,
                    nullptr,       name,
                    content.color, instances.translation.empty() ? nullptr : &instances};
  out.bytes = make_glb({prim});
  return out;
}

}  // namespace maquette
