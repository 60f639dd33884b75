// The mesh plug-in's entry point for the runner: formats/gltf's mesh GLB in its envelope.
#include "plugins/content_encode.h"

#include "gltf/mesh_glb.h"

void maquette_mesh_content_blob(const maquette::MeshContent& content, std::string& blob) {
  blob = maquette::mesh_content_blob(content);
}
