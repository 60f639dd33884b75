// `maquette export glb` (the terrain of a few cells in one GLB) and `maquette export drc`
// (one raw Draco mesh per cell, OUTDIR/<CELL>.drc, and OUTDIR/frame.json giving the frame).
// Cells are exported at their own levels (coarser than the DEM: its overviews); all meshes share
// one east-north-up frame (glTF axes: x east, y up, z south), named in the asset's extras, each
// measured from an offset in it at the mesh (its node's translation; for drc, frame.json's
// "offsets": {"CELL": [x, y, z]}).
#pragma once

#include <string>
#include <vector>

#include "core/grid.h"
#include "gltf/terrain_level.h"

namespace maquette {

void export_glb(const Store& store, const Grid& grid, const TerrainSettings& settings,
                const std::vector<CellId>& cells, const std::string& out);
void export_drc(const Store& store, const Grid& grid, const TerrainSettings& settings,
                const std::vector<CellId>& cells, const std::string& out_dir);

// The frame as JSON: {"origin": {"lon", "lat", "height"}, "axes": "x east, y up, z south"}.
nlohmann::json frame_json(const LocalFrame& frame);

}  // namespace maquette
