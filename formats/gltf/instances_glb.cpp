#include "gltf/instances_glb.h"

#include <deque>
#include <string>

#include "core/error.h"
#include "gltf/glb_writer.h"

namespace maquette {
namespace {

// Throws unless `column` has `per` values per instance.
template <typename T>
void check_column(const std::vector<T>& column, size_t per, size_t count, const char* name) {
  if (column.size() != per * count)
    throw Error("instances content: column " + std::string(name) + " has " +
                std::to_string(column.size()) + " values for " + std::to_string(count) +
                " instances (" + std::to_string(per) + " per instance)");
}

// An object's geometry in glTF's axes: (east, north, up) -> (east, up, -north); uvs as they are.
TerrainMesh gltf_mesh(const MeshObject& o) {
  TerrainMesh m;
  for (size_t i = 0; i + 2 < o.positions.size(); i += 3)
    m.positions.insert(m.positions.end(),
                       {o.positions[i], o.positions[i + 2], -o.positions[i + 1]});
  for (size_t i = 0; i + 2 < o.normals.size(); i += 3)
    m.normals.insert(m.normals.end(), {o.normals[i], o.normals[i + 2], -o.normals[i + 1]});
  m.texcoords = o.uvs;
  m.indices = o.indices;
  return m;
}

// The instances of prototype `p`, in glTF's axes: a rotation's axis turns as a vector does, and
// the scales along the prototype's axes are swapped as its axes are.
InstanceTransforms transforms_of(const InstancesContent& c, size_t p) {
  InstanceTransforms t;
  for (size_t i = 0; i < c.size(); ++i) {
    if (c.prototype[i] != p) continue;
    const float* x = &c.position[3 * i];
    const float* q = &c.rotation[4 * i];
    const float* s = &c.scale[3 * i];
    t.translation.insert(t.translation.end(), {x[0], x[2], -x[1]});
    t.rotation.insert(t.rotation.end(), {q[0], q[2], -q[1], q[3]});
    t.scale.insert(t.scale.end(), {s[0], s[2], s[1]});
    for (int k = 0; k < 4; ++k) t.colour.push_back(uint8_t(c.colour[i] >> (8 * k)));
  }
  return t;
}

}  // namespace

std::vector<char> instances_glb(const InstancesContent& content,
                                const std::vector<const MeshContent*>& prototypes) {
  const size_t n = content.size();
  if (n == 0) throw Error("instances content: no instances (a cell without any has no content)");
  check_column(content.position, 3, n, "position");
  check_column(content.rotation, 4, n, "rotation");
  check_column(content.scale, 3, n, "scale");
  check_column(content.colour, 1, n, "colour");
  if (prototypes.size() != content.prototypes.size())
    throw Error("instances content: " + std::to_string(content.prototypes.size()) +
                " prototypes named, " + std::to_string(prototypes.size()) + " models given");
  for (size_t i = 0; i < n; ++i)
    if (content.prototype[i] >= prototypes.size())
      throw Error("instances content: instance " + std::to_string(i) + " has prototype " +
                  std::to_string(content.prototype[i]) + " of " +
                  std::to_string(prototypes.size()));
  // Kept at fixed addresses: the primitives point into them.
  std::deque<InstanceTransforms> transforms;
  std::deque<TerrainMesh> meshes;
  std::vector<GlbPrimitive> primitives;
  for (size_t p = 0; p < prototypes.size(); ++p) {
    const std::string& name = content.prototypes[p];
    if (!prototypes[p]) throw Error("instances content: no model for prototype '" + name + "'");
    const MeshContent& model = *prototypes[p];
    transforms.push_back(transforms_of(content, p));
    if (transforms.back().translation.empty()) continue;
    for (const MeshObject& o : model.objects) {
      const Material* material =
          o.material >= 0 ? &model.materials.at(size_t(o.material)) : nullptr;
      GlbPrimitive prim;
      prim.mesh = &meshes.emplace_back(gltf_mesh(o));
      prim.name = name + (material ? " " + material->name : "");
      prim.material = material;  // its image written once, whatever the objects drawing it
      prim.instances = &transforms.back();
      primitives.push_back(prim);
    }
  }
  const EnuOrigin& o = content.origin;
  return make_glb(primitives, {{"origin", {{"lon", o.lon}, {"lat", o.lat}, {"height", o.height}}},
                               {"axes", "x east, y up, z south"}});
}

}  // namespace maquette
