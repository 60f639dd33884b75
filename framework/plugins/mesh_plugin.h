// The mesh plug-in's file (runtime/plugin.h opens it by name): the one place that names it, for
// the exports (mesh_export.h), the overviews (mesh_overviews.h) and the runner's content encoding
// (content_encode.h), so that code which must not include mesh_export.h (it brings the exports'
// headers, Draco's among them) names the same file.
#pragma once

namespace maquette {

inline constexpr const char* kMeshPlugin = "libmaquette_mesh.so";

}  // namespace maquette
