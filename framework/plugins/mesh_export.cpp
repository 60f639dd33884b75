// The mesh plug-in's entry points: the exports of formats/gltf and formats/tiles3d.
#include "plugins/mesh_export.h"

#include "gltf/export_glb.h"

int64_t maquette_mesh_tiles3d(const maquette::Store& store, const maquette::Grid& grid,
                              const maquette::Tiles3dExport& spec, const std::string& out_dir) {
  return maquette::export_tiles3d(store, grid, spec, out_dir);
}

void maquette_mesh_glb(const maquette::Store& store, const maquette::Grid& grid,
                       const maquette::GlbExport& spec, const std::vector<maquette::CellId>& cells,
                       const std::string& out) {
  maquette::export_glb(store, grid, spec, cells, out);
}

void maquette_mesh_drc(const maquette::Store& store, const maquette::Grid& grid,
                       const maquette::TerrainSettings& settings,
                       const std::vector<maquette::CellId>& cells, const std::string& out_dir) {
  maquette::export_drc(store, grid, settings, cells, out_dir);
}
