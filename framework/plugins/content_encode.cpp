// The mesh plug-in's entry point for the runner: formats/gltf's mesh GLB in its envelope.
#include "plugins/content_encode.h"

#include "content/content_blob.h"
#include "gltf/mesh_glb.h"

void maquette_mesh_content_blob(const maquette::MeshContent& content, std::string& blob) {
  maquette::ContentEnvelope envelope;
  envelope.kind = maquette::ContentKind::Mesh;
  envelope.origin = content.origin;
  envelope.stats.objects = content.objects.size();
  for (const maquette::MeshObject& o : content.objects)
    envelope.stats.triangles += o.indices.size() / 3;
  blob = maquette::wrap_content(envelope, maquette::encode_mesh_glb(content));
}
