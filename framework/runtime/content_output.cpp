#include "runtime/content_output.h"

#include <spdlog/fmt/fmt.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "content/content_blob.h"
#include "content/enu_transform.h"
#include "content/instances_codec.h"
#include "content/prototypes.h"
#include "core/enu_frame.h"
#include "core/error.h"
#include "plugins/content_encode.h"
#include "plugins/vdb_content.h"
#include "runtime/plugin.h"

namespace maquette {
namespace {

std::string object_text(const MeshObject& o, size_t i) {
  return "mesh object " + std::to_string(i) + " (feature " +
         std::to_string(o.provenance.feature_id) + ")";
}

std::string instance_text(const InstancesContent& c, size_t i) {
  const int64_t feature = c.provenance.empty() ? -1 : c.provenance[i].feature_id;
  return "instance " + std::to_string(i) + " (feature " + std::to_string(feature) + ")";
}

bool finite3(const float* p) {
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

// Throws unless the anchor at `xyz` (finite) lies in `cell`, or within kAnchorToleranceM of it:
// float32 positions near an edge may round across it.
void check_anchor(const EnuOrigin& origin, const float* xyz, CellId cell, const Grid& grid,
                  const std::string& what) {
  const EnuFrame frame = enu_frame(origin);
  const auto cell_at = [&](double dx, double dy) {
    const GeodeticPoint p =
        frame.to_geodetic(double(xyz[0]) + dx, double(xyz[1]) + dy, double(xyz[2]));
    return grid.cell_from_point({p.lon, p.lat}, cell.level());
  };
  const CellId at = cell_at(0, 0);
  if (at == cell) return;
  const double t = kAnchorToleranceM;
  for (const double dx : {-t, 0.0, t})
    for (const double dy : {-t, 0.0, t})
      if (cell_at(dx, dy) == cell) return;
  const GeodeticPoint p = frame.to_geodetic(xyz[0], xyz[1], xyz[2]);
  throw Error(
      fmt::format("{}: its anchor at lon {:.8f}, lat {:.8f} lies in cell {}, not in this "
                  "cell (each cell writes only the objects it owns: CellContext::owns)",
                  what, p.lon, p.lat, at.ToText()));
}

void check_mesh(const MeshContent& c, CellId cell, const Grid& grid) {
  for (size_t i = 0; i < c.objects.size(); ++i) {
    const MeshObject& o = c.objects[i];
    const auto fail = [&](const std::string& fault) {
      throw Error(object_text(o, i) + ": " + fault);
    };
    const size_t vertices = o.positions.size() / 3;
    if (vertices == 0 || o.positions.size() % 3 != 0)
      fail(std::to_string(o.positions.size()) + " position values: not 3 per vertex, or none");
    for (size_t v = 0; v < vertices; ++v)
      if (!finite3(&o.positions[3 * v]))
        fail(fmt::format("vertex {} at ({}, {}, {}) is not finite", v, o.positions[3 * v],
                         o.positions[3 * v + 1], o.positions[3 * v + 2]));
    if (!o.normals.empty() && o.normals.size() != o.positions.size())
      fail(std::to_string(o.normals.size()) + " normal values for " + std::to_string(vertices) +
           " vertices");
    if (!o.uvs.empty() && o.uvs.size() != 2 * vertices)
      fail(std::to_string(o.uvs.size()) + " uv values for " + std::to_string(vertices) +
           " vertices");
    if (o.indices.empty() || o.indices.size() % 3 != 0)
      fail(std::to_string(o.indices.size()) + " indices: not whole triangles, or none");
    const auto bad =
        std::find_if(o.indices.begin(), o.indices.end(), [&](uint32_t k) { return k >= vertices; });
    if (bad != o.indices.end())
      fail("index " + std::to_string(*bad) + " is out of range (" + std::to_string(vertices) +
           " vertices)");
    if (o.material < -1 || o.material >= int(c.materials.size()))
      fail("material " + std::to_string(o.material) + " is out of range (" +
           std::to_string(c.materials.size()) + " materials)");
    check_anchor(c.origin, o.positions.data(), cell, grid, object_text(o, i));
  }
}

// Prototype names must be built in or name a model layer (`maquette ingest --as model`).
void check_prototypes(const InstancesContent& c, const std::set<std::string>& models) {
  const auto& builtin = builtin_prototype_names();
  for (size_t p = 0; p < c.prototypes.size(); ++p) {
    if (std::find(builtin.begin(), builtin.end(), c.prototypes[p]) != builtin.end() ||
        models.count(c.prototypes[p]))
      continue;
    const auto user = std::find(c.prototype.begin(), c.prototype.end(), uint16_t(p));
    std::string known;
    for (const std::string& name : builtin) known += (known.empty() ? "" : ", ") + name;
    for (const std::string& name : models) known += ", " + name;
    throw Error((user == c.prototype.end() ? "prototype " + std::to_string(p)
                                           : instance_text(c, size_t(user - c.prototype.begin()))) +
                ": unknown prototype '" + c.prototypes[p] + "' (known: " + known + ")");
  }
}

void check_instance_positions(const InstancesContent& c, CellId cell, const Grid& grid) {
  for (size_t i = 0; i < c.size(); ++i) {
    const float* p = &c.position[3 * i];
    if (!finite3(p))
      throw Error(fmt::format("{}: position ({}, {}, {}) is not finite", instance_text(c, i), p[0],
                              p[1], p[2]));
    check_anchor(c.origin, p, cell, grid, instance_text(c, i));
  }
}

std::string mesh_blob(const MeshContent& c, CellId cell, const Grid& grid) {
  check_mesh(c, cell, grid);
  static auto* const encode =
      plugin_function<decltype(maquette_mesh_content_blob)>(kMeshPlugin, kMeshContentEntry);
  std::string blob;
  encode(c, blob);
  return blob;
}

std::string instances_blob(const InstancesContent& c, CellId cell, const Grid& grid,
                           const std::set<std::string>& models) {
  check_instances(c, "instances content");  // the columns first: the positions below are then there
  check_prototypes(c, models);
  check_instance_positions(c, cell, grid);
  return wrap_instances(c);
}

// Each grid's anchor (the centre of its active voxels' bounding box) in the cell.
void check_volume_anchors(const VolumeContent& c, CellId cell, const Grid& grid) {
  static auto* const anchors_of =
      plugin_function<decltype(maquette_vdb_anchors)>(kVdbPlugin, kVdbAnchorsEntry);
  std::vector<std::optional<std::array<double, 3>>> anchors;
  anchors_of(c, "volume", anchors);
  for (size_t i = 0; i < anchors.size(); ++i)
    if (const auto& a = anchors[i]) {
      const float xyz[3] = {float((*a)[0]), float((*a)[1]), float((*a)[2])};
      check_anchor(c.origin, xyz, cell, grid, "volume grid " + std::to_string(i));
    }
}

std::string volume_blob(const VolumeContent& c, CellId cell, const Grid& grid) {
  check_volume_anchors(c, cell, grid);
  static auto* const stats_of =
      plugin_function<decltype(maquette_vdb_stats)>(kVdbPlugin, kVdbStatsEntry);
  ContentEnvelope envelope;
  envelope.kind = ContentKind::Volume;
  envelope.origin = c.origin;
  stats_of(c, "volume", envelope.stats);
  return wrap_content(envelope, c.vdb);
}

template <class Content, class Encode>
void encode_port(const std::map<std::string, Content>& by_port, std::vector<ContentBlob>& out,
                 const Encode& encode) {
  for (const auto& [port, content] : by_port) try {
      if (std::string blob = encode(content); !blob.empty()) out.push_back({port, std::move(blob)});
    } catch (const std::exception& e) {
      throw Error("outputs." + port + ": " + e.what());
    }
}

}  // namespace

std::vector<ContentBlob> encode_cell_content(const CellContent& content, CellId cell,
                                             const Grid& grid,
                                             const std::set<std::string>& models) {
  std::vector<ContentBlob> blobs;
  // The origin first: the anchors' checks go through it.
  const auto origin_ok = [](const auto& c) {
    if (const std::string fault = origin_fault(c.origin); !fault.empty()) throw Error(fault);
  };
  encode_port(content.meshes, blobs, [&](const MeshContent& c) {
    if (c.objects.empty()) return std::string();
    origin_ok(c);
    return mesh_blob(c, cell, grid);
  });
  encode_port(content.instances, blobs, [&](const InstancesContent& c) {
    if (c.size() == 0) return std::string();
    origin_ok(c);
    return instances_blob(c, cell, grid, models);
  });
  encode_port(content.volumes, blobs, [&](const VolumeContent& c) {
    if (c.vdb.empty()) return std::string();
    origin_ok(c);
    return volume_blob(c, cell, grid);
  });
  return blobs;
}

}  // namespace maquette
