// The mesh plug-in, libmaquette_mesh.so: the exports that build Draco-compressed meshes (3D Tiles,
// GLB, Draco files), opened by those exports only, so no other command loads Draco.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gltf/export_glb.h"
#include "gltf/terrain_level.h"
#include "plugins/mesh_plugin.h"
#include "tiles3d/export_tiles3d.h"

namespace maquette {

inline constexpr const char* kTiles3dEntry = "maquette_mesh_tiles3d";
inline constexpr const char* kGlbEntry = "maquette_mesh_glb";
inline constexpr const char* kDrcEntry = "maquette_mesh_drc";

}  // namespace maquette

// export_tiles3d (tiles3d/export_tiles3d.h): the number of tiles written.
extern "C" int64_t maquette_mesh_tiles3d(const maquette::Store& store, const maquette::Grid& grid,
                                         const maquette::Tiles3dExport& spec,
                                         const std::string& out_dir);
// export_glb and export_drc (gltf/export_glb.h).
extern "C" void maquette_mesh_glb(const maquette::Store& store, const maquette::Grid& grid,
                                  const maquette::GlbExport& spec,
                                  const std::vector<maquette::CellId>& cells,
                                  const std::string& out);
extern "C" void maquette_mesh_drc(const maquette::Store& store, const maquette::Grid& grid,
                                  const maquette::TerrainSettings& settings,
                                  const std::vector<maquette::CellId>& cells,
                                  const std::string& out_dir);
