// The mesh plug-in's encoding of a cell's mesh content for the store (issue 15): the blob the
// runner writes with Batch::put_content, built here because the GLB is Draco-compressed and
// libmaquette does not link Draco.
#pragma once

#include <string>

#include "content/content.h"
#include "plugins/mesh_plugin.h"

namespace maquette {

inline constexpr const char* kMeshContentEntry = "maquette_mesh_content_blob";

}  // namespace maquette

// `content` as a mesh layer's blob: gltf/mesh_glb.h's mesh_content_blob (positions quantized to
// at most 1 mm). Throws maquette::Error as it does.
extern "C" void maquette_mesh_content_blob(const maquette::MeshContent& content, std::string& blob);
