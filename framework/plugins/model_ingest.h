// Models into the store (`maquette ingest --as model`), in the mesh plug-in libmaquette_mesh.so:
// reading glTF and encoding the mesh GLB need Draco, which no other command loads.
#pragma once

#include <string>

#include "content/content.h"

namespace maquette {

inline constexpr const char* kModelIngestEntry = "maquette_mesh_model";

// Moves the model up or down so that its lowest vertex is at z = 0 (its base on the ground); x
// and y are kept, so the model's origin stays the point it is placed at. Precondition: finite
// positions (a model without vertices is left as it is).
void place_base_at_zero(MeshContent& model);

}  // namespace maquette

// The blob of a model layer (Store::Batch::put_model) from the glTF model at `path` (.glb, or
// .gltf with its buffers and images): read_gltf_model (gltf/gltf_model.h: glTF's y up becomes z
// up, the model's origin is the content's), place_base_at_zero, then a mesh GLB
// (gltf/mesh_glb.h, default settings: positions within 1 mm) in a mesh envelope at the zero
// origin, into `blob`. Throws maquette::Error naming the file and the fault: not glTF, no mesh,
// a buffer declaring more than 1 GiB (before anything is allocated for it), a missing buffer or
// image file, bad accessors, non-finite positions.
extern "C" void maquette_mesh_model(const std::string& path, std::string& blob);
