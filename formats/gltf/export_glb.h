// `maquette export glb` (the terrain and 3D content of a few cells in one GLB) and
// `maquette export drc` (one raw Draco terrain mesh per cell, OUTDIR/<CELL>.drc, and
// OUTDIR/frame.json giving the frame). Cells are exported at their own levels (coarser than the
// DEM: its overviews; coarser than a content layer: its simplified copies); everything shares one
// east-north-up frame at the centre of the cells (glTF axes: x east, y up, z south), named in
// the asset's extras ("maquette_frame"). Terrain meshes are measured from an offset in it at the
// mesh (its node's translation; for drc, frame.json's "offsets": {"CELL": [x, y, z]}); each
// cell's content (gltf/cell_content.h) stays in its own frame under a node named "LAYER CELL"
// whose matrix places that frame in the export's, computed in double through ECEF
// (frame_to_frame), the terrain under a node "terrain" (gltf/glb_merge.h).
#pragma once

#include <string>
#include <vector>

#include "core/grid.h"
#include "gltf/terrain_level.h"

namespace maquette {

struct GlbExport {
  TerrainSettings terrain;           // terrain.dem empty: no terrain
  std::vector<std::string> content;  // 3D content layers (kinds mesh, instances, volume)
};

// Throws maquette::Error when neither terrain nor content is asked, when no cell holds any of the
// content asked (and no terrain is), and as the terrain and content readers do.
void export_glb(const Store& store, const Grid& grid, const GlbExport& spec,
                const std::vector<CellId>& cells, const std::string& out);
void export_drc(const Store& store, const Grid& grid, const TerrainSettings& settings,
                const std::vector<CellId>& cells, const std::string& out_dir);

// The frame as JSON: {"origin": {"lon", "lat", "height"}, "axes": "x east, y up, z south"}.
nlohmann::json frame_json(const LocalFrame& frame);

}  // namespace maquette
