#include "stored_content.h"

#include <GeographicLib/LocalCartesian.hpp>

#include "content/content_blob.h"
#include "content/instances_codec.h"
#include "gltf/mesh_glb.h"

namespace maquette::test {

std::vector<StoredMeshes> stored_meshes(const Store& store, const std::string& layer) {
  std::vector<StoredMeshes> out;
  for (const CellId cell : store.content_cells(layer)) {
    const std::string blob = *store.get_content(layer, cell);
    const ContentEnvelope envelope = read_content_envelope(blob, "test");
    out.push_back(
        {envelope.origin, decode_mesh_glb(content_payload(blob), envelope.origin, "test")});
  }
  return out;
}

std::array<double, 3> enu_to_geodetic(const EnuOrigin& origin, double east, double north,
                                      double up) {
  std::array<double, 3> g{};
  GeographicLib::LocalCartesian(origin.lat, origin.lon, origin.height)
      .Reverse(east, north, up, g[1], g[0], g[2]);
  return g;
}

std::vector<StoredInstance> stored_instances(const Store& store, const std::string& layer) {
  std::vector<StoredInstance> out;
  for (const CellId cell : store.content_cells(layer)) {
    const InstancesContent c = unwrap_instances(*store.get_content(layer, cell), "test");
    for (size_t i = 0; i < c.size(); ++i) {
      StoredInstance p;
      const float* pos = &c.position[3 * i];
      const std::array<double, 3> at = enu_to_geodetic(c.origin, pos[0], pos[1], pos[2]);
      p.lon = at[0], p.lat = at[1], p.height = at[2];
      // The model's +x turned by the quaternion, as a point 1 m from the position, seen in the
      // position's own east-north-up frame.
      const double qx = c.rotation[4 * i], qy = c.rotation[4 * i + 1], qz = c.rotation[4 * i + 2],
                   qw = c.rotation[4 * i + 3];
      const std::array<double, 3> end =
          enu_to_geodetic(c.origin, pos[0] + 1 - 2 * (qy * qy + qz * qz),
                          pos[1] + 2 * (qx * qy + qw * qz), pos[2] + 2 * (qx * qz - qw * qy));
      GeographicLib::LocalCartesian(p.lat, p.lon, p.height)
          .Forward(end[1], end[0], end[2], p.x_axis[0], p.x_axis[1], p.x_axis[2]);
      p.scale = {c.scale[3 * i], c.scale[3 * i + 1], c.scale[3 * i + 2]};
      p.prototype = c.prototypes[c.prototype[i]];
      if (!c.provenance.empty()) p.provenance = c.provenance[i];
      out.push_back(std::move(p));
    }
  }
  return out;
}

}  // namespace maquette::test
