// The mesh plug-in's model ingest: an outside glTF model as a model layer's blob.
#include "plugins/model_ingest.h"

#include <algorithm>
#include <limits>

#include "core/error.h"
#include "gltf/gltf_model.h"
#include "gltf/mesh_glb.h"

namespace maquette {

void place_base_at_zero(MeshContent& model) {
  float base = std::numeric_limits<float>::infinity();
  for (const MeshObject& o : model.objects)
    for (size_t i = 2; i < o.positions.size(); i += 3) base = std::min(base, o.positions[i]);
  if (base == std::numeric_limits<float>::infinity()) return;
  for (MeshObject& o : model.objects)
    for (size_t i = 2; i < o.positions.size(); i += 3) o.positions[i] -= base;
}

}  // namespace maquette

void maquette_mesh_model(const std::string& path, std::string& blob) {
  using namespace maquette;
  MeshContent model = read_gltf_model(path);
  place_base_at_zero(model);
  try {
    blob = mesh_content_blob(model);  // the model's origin fields stay zero
  } catch (const Error& e) {
    throw Error(path + ": " + e.what());
  }
}
