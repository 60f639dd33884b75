#include "gltf/cell_content.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "content/content_blob.h"
#include "content/enu_transform.h"
#include "content/glb_chunks.h"
#include "content/instances_codec.h"
#include "core/error.h"
#include "gltf/glb_merge.h"
#include "gltf/instances_glb.h"
#include "gltf/mesh_glb.h"
#include "plugins/vdb_content.h"
#include "runtime/plugin.h"

namespace maquette {
namespace {

using nlohmann::json;
using Box = std::array<Vec3, 2>;  // min, max corners in a content's ENU frame (metres)

constexpr double kPad = 0.01;  // metres around a content's box in its region
constexpr double kEarthRadius = 6371008.8;

Box empty_box() {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  return {Vec3{kInf, kInf, kInf}, Vec3{-kInf, -kInf, -kInf}};
}

void extend(Box& b, const Vec3& lo, const Vec3& hi) {
  for (size_t k = 0; k < 3; ++k) {
    b[0][k] = std::min(b[0][k], lo[k]);
    b[1][k] = std::max(b[1][k], hi[k]);
  }
}

// The region of a box in the ENU frame at `o`, padded: the box's points at x and y of its sides
// and of the origin's vertical (clamped to the box), at its bottom and top. Those hold the
// extremes: the ellipsoid curves away from the frame's plane, so the bottom is lowest (and a
// north or south side reaches farthest in latitude) nearest the origin's vertical, and the top
// highest at its corners. A box across the antimeridian or reaching a pole gets every longitude
// (tileset.h's regions keep west <= east).
std::array<double, 6> box_region(const EnuOrigin& o, const Box& b) {
  const EnuFrame frame = enu_frame(o);
  std::vector<Vec3> points;
  for (const double x : {b[0][0], std::clamp(0.0, b[0][0], b[1][0]), b[1][0]})
    for (const double y : {b[0][1], std::clamp(0.0, b[0][1], b[1][1]), b[1][1]})
      for (const double z : {b[0][2], b[1][2]}) points.push_back({x, y, z});
  constexpr double kPi = std::numbers::pi, rad = kPi / 180;
  std::array<double, 6> r = {kPi,
                             kPi,
                             -kPi,
                             -kPi,
                             std::numeric_limits<double>::infinity(),
                             -std::numeric_limits<double>::infinity()};
  double lon_lo = 360, lon_hi = -360;  // from the origin's longitude, unwrapped
  for (const Vec3& p : points) {
    const GeodeticPoint g = frame.to_geodetic(p[0], p[1], p[2]);
    const double dlon = std::remainder(g.lon - o.lon, 360.0);
    lon_lo = std::min(lon_lo, dlon);
    lon_hi = std::max(lon_hi, dlon);
    r[1] = std::min(r[1], g.lat * rad);
    r[3] = std::max(r[3], g.lat * rad);
    r[4] = std::min(r[4], g.height - kPad);
    r[5] = std::max(r[5], g.height + kPad);
  }
  const double dlat = kPad / kEarthRadius;
  r[1] = std::max(-kPi / 2, r[1] - dlat);
  r[3] = std::min(kPi / 2, r[3] + dlat);
  const double dlon = dlat / std::max(1e-9, std::cos(std::max(std::abs(r[1]), std::abs(r[3]))));
  const double west = (o.lon + lon_lo) * rad - dlon, east = (o.lon + lon_hi) * rad + dlon;
  const bool all_longitudes = west < -kPi || east > kPi || r[1] == -kPi / 2 || r[3] == kPi / 2;
  r[0] = all_longitudes ? -kPi : west;
  r[2] = all_longitudes ? kPi : east;
  return r;
}

// The box of every primitive's POSITION bounds (glTF requires them), in ENU: mesh_glb's one node
// has no transform.
Box mesh_box(const json& gltf, const std::string& where) {
  Box box = empty_box();
  try {
    for (const json& mesh : gltf.at("meshes"))
      for (const json& prim : mesh.at("primitives")) {
        const json& a = gltf.at("accessors").at(prim.at("attributes").at("POSITION").get<size_t>());
        const Vec3 lo = a.at("min").get<Vec3>(), hi = a.at("max").get<Vec3>();
        // glTF (x, y, z) = (east, up, -north): north spans -max z .. -min z.
        extend(box, {lo[0], -hi[2], lo[1]}, {hi[0], -lo[2], hi[1]});
      }
  } catch (const json::exception& e) {
    throw Error("content GLB (" + where + "): no POSITION bounds (" + e.what() + ")");
  }
  return box;
}

CellGlb mesh_content(std::string glb, const EnuOrigin& origin, const std::string& where) {
  const Box box = mesh_box(split_glb(glb, "content GLB (" + where + ")").gltf, where);
  return {std::move(glb), origin, box_region(origin, box)};
}

// The largest distance of a model's vertex from its origin (a sphere holding it, any rotation).
double model_radius(const MeshContent& model) {
  double r2 = 0;
  for (const MeshObject& o : model.objects)
    for (size_t i = 0; i + 2 < o.positions.size(); i += 3)
      r2 = std::max(r2, double(o.positions[i]) * o.positions[i] +
                            double(o.positions[i + 1]) * o.positions[i + 1] +
                            double(o.positions[i + 2]) * o.positions[i + 2]);
  return std::sqrt(r2);
}

std::optional<CellGlb> instances_content(const InstancesContent& c,
                                         const std::vector<const MeshContent*>& models) {
  if (c.size() == 0) return std::nullopt;
  std::vector<double> radius;
  for (const MeshContent* m : models) radius.push_back(model_radius(*m));
  Box box = empty_box();
  for (size_t i = 0; i < c.size(); ++i) {
    const float* s = &c.scale[3 * i];
    const double r =
        radius[c.prototype[i]] * std::max({std::abs(s[0]), std::abs(s[1]), std::abs(s[2])});
    const Vec3 p = {c.position[3 * i], c.position[3 * i + 1], c.position[3 * i + 2]};
    extend(box, {p[0] - r, p[1] - r, p[2] - r}, {p[0] + r, p[1] + r, p[2] + r});
  }
  const std::vector<char> glb = instances_glb(c, models);
  return CellGlb{{glb.begin(), glb.end()}, c.origin, box_region(c.origin, box)};
}

std::optional<CellGlb> volume_content(const VolumeContent& volume, const std::string& where) {
  static auto* const mesh_volume =
      plugin_function<decltype(maquette_vdb_mesh)>(kVdbPlugin, kVdbMeshEntry);
  MeshContent mesh;
  mesh_volume(volume, VolumeMeshSettings{}, where, mesh);
  std::erase_if(mesh.objects, [](const MeshObject& o) { return o.indices.empty(); });
  if (mesh.objects.empty()) return std::nullopt;
  mesh.origin = volume.origin;
  return mesh_content(encode_mesh_glb(mesh), volume.origin, where);
}

}  // namespace

std::array<double, 16> frame_to_frame(const EnuOrigin& from, const LocalFrame& to) {
  const std::array<double, 16> enu =
      EnuTransform(from, {to.origin().lon, to.origin().lat, 0}).matrix();  // row-major, ENU axes
  // glTF axis k is ENU axis kAxis[k] times kSign[k] (x east, y up, z south).
  constexpr std::array<size_t, 3> kAxis = {0, 2, 1};
  constexpr std::array<double, 3> kSign = {1, 1, -1};
  std::array<double, 16> m{};
  for (size_t r = 0; r < 3; ++r) {
    for (size_t c = 0; c < 3; ++c)
      m[4 * c + r] = kSign[r] * kSign[c] * enu[4 * kAxis[r] + kAxis[c]];
    m[12 + r] = kSign[r] * enu[4 * kAxis[r] + 3];  // the translation
  }
  m[15] = 1;
  return m;
}

void require_content_layer(const Store& store, const std::string& layer) {
  const auto info = store.layer(layer);
  if (!info || !layer_content_kind(info->kind))
    throw Error("no content layer '" + layer + "' in " + store.path() + " (" +
                (info ? "it is a " + std::string(layer_kind_name(info->kind)) + " layer"
                      : "no such layer") +
                "; content layers are of kind mesh, instances or volume)");
}

std::optional<CellGlb> CellContentReader::read(const std::string& layer, CellId cell) {
  const std::optional<std::string> blob = store_.get_content(layer, cell);
  if (!blob) return std::nullopt;
  const std::string where = "layer " + layer + ", cell " + cell.ToText();
  const ContentEnvelope e = read_content_envelope(*blob, where);
  switch (e.kind) {
    case ContentKind::Mesh:
      return mesh_content(std::string(content_payload(*blob)), e.origin, where);
    case ContentKind::Instances: {
      const InstancesContent c = unwrap_instances(*blob, where);
      return instances_content(c, prototypes_.models(c, where));
    }
    case ContentKind::Volume:
      return volume_content({e.origin, std::string(content_payload(*blob))}, where);
  }
  return std::nullopt;
}

}  // namespace maquette
