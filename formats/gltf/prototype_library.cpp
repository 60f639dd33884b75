#include "gltf/prototype_library.h"

#include <algorithm>
#include <optional>

#include "content/content_blob.h"
#include "content/prototypes.h"
#include "core/error.h"
#include "gltf/mesh_glb.h"

namespace maquette {

std::vector<const MeshContent*> PrototypeLibrary::models(const InstancesContent& content,
                                                         const std::string& where) {
  std::vector<const MeshContent*> out;
  for (const std::string& name : content.prototypes) {
    auto it = models_.find(name);
    if (it == models_.end()) {
      const auto& builtins = builtin_prototype_names();
      if (std::ranges::find(builtins, name) != builtins.end()) {
        it = models_.emplace(name, &builtin_prototype(name)).first;
      } else if (const std::optional<std::string> blob = store_.get_model(name)) {
        const std::string model = "model layer " + name;
        const ContentEnvelope envelope = read_content_envelope(*blob, model);
        const MeshContent& mesh =
            decoded_.emplace(name, decode_mesh_glb(content_payload(*blob), envelope.origin, model))
                .first->second;
        it = models_.emplace(name, &mesh).first;
      } else {
        throw Error(where + ": unknown prototype '" + name +
                    "' (builtin:conifer, builtin:broadleaf, builtin:shrub or a model layer of " +
                    store_.path() + ")");
      }
    }
    out.push_back(it->second);
  }
  return out;
}

}  // namespace maquette
