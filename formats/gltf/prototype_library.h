// The models of an instances content's prototype names (content/content.h: InstancesContent),
// for an export: "builtin:*" names are the built-in prototypes (content/prototypes.h); any other
// name is a model layer of the same store (`maquette ingest --as model`: a mesh GLB in the
// model's frame, decoded here). Each model is made or read once per library, so one library
// serves a whole export.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "content/content.h"
#include "store/store.h"

namespace maquette {

class PrototypeLibrary {
 public:
  explicit PrototypeLibrary(const Store& store) : store_(store) {}

  // The model of each of content.prototypes, in their order (pointers into the library, valid
  // while it lives). Throws maquette::Error naming `where` (e.g. "layer trees, cell N3021") and
  // the name for an unknown prototype, listing the names that are known.
  std::vector<const MeshContent*> models(const InstancesContent& content, const std::string& where);

 private:
  const Store& store_;
  std::map<std::string, const MeshContent*> models_;
  std::map<std::string, MeshContent> decoded_;  // the model layers read so far
};

}  // namespace maquette
