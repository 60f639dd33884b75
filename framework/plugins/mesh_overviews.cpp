// The mesh plug-in's entry for mesh layers' coarser levels: formats/gltf.
#include "plugins/mesh_overviews.h"

#include "content/content_blob.h"
#include "gltf/mesh_glb.h"
#include "gltf/mesh_simplify.h"

void maquette_mesh_overview(const std::vector<std::string>& children,
                            const maquette::ContentLevel& level, const std::string& where,
                            std::optional<std::string>& overview) {
  using namespace maquette;
  std::vector<MeshContent> decoded;
  for (const std::string& blob : children) {
    const ContentEnvelope envelope = read_content_envelope(blob, where);
    decoded.push_back(decode_mesh_glb(content_payload(blob), envelope.origin, where));
  }
  const MeshContent parent = simplify_mesh_children(decoded, level);
  overview.reset();
  if (parent.objects.empty()) return;
  overview = mesh_content_blob(parent);
}
