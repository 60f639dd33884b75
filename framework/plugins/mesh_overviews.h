// The mesh plug-in's builder of mesh layers' coarser levels (content/content_overviews.h), so
// that libmaquette reaches Draco and meshoptimizer only through libmaquette_mesh.so.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "content/content_overviews.h"

namespace maquette {

inline constexpr const char* kMeshOverviewEntry = "maquette_mesh_overview";

}  // namespace maquette

// A ContentOverviewBuilder: the children's mesh blobs decoded (gltf/mesh_glb.h), simplified
// (gltf/mesh_simplify.h) and encoded again in the envelope of level.origin (objects and
// triangles counted); nullopt when no object is left.
extern "C" void maquette_mesh_overview(const std::vector<std::string>& children,
                                       const maquette::ContentLevel& level,
                                       const std::string& where,
                                       std::optional<std::string>& overview);
