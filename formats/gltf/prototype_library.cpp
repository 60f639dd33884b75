#include "gltf/prototype_library.h"

#include <algorithm>

#include "content/prototypes.h"
#include "core/error.h"

namespace maquette {

std::vector<const MeshContent*> PrototypeLibrary::models(const InstancesContent& content,
                                                         const std::string& where) {
  std::vector<const MeshContent*> out;
  for (const std::string& name : content.prototypes) {
    auto it = models_.find(name);
    if (it == models_.end()) {
      const auto& builtins = builtin_prototype_names();
      if (std::ranges::find(builtins, name) == builtins.end())
        throw Error(where + ": unknown prototype '" + name +
                    "' (builtin:conifer, builtin:broadleaf, builtin:shrub or a model layer of " +
                    store_.path() + ")");
      it = models_.emplace(name, &builtin_prototype(name)).first;
    }
    out.push_back(it->second);
  }
  return out;
}

}  // namespace maquette
