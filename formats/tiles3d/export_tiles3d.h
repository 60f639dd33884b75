// `maquette export tiles3d`: the terrain of a region as a 3D Tiles 1.1 tileset whose tile tree is
// the cell tree, one Draco-compressed GLB per cell and level (OUTDIR/tiles/<LEVEL>/<CELL>.glb).
// All meshes share the export's east-north-up frame (glTF y-up), placed on the globe by the root
// tile's transform; geometric error of a level is its vertex spacing (0 at the finest level).
#pragma once

#include <string>
#include <vector>

#include "core/grid.h"
#include "gltf/terrain_level.h"
#include "image/layer_cells.h"

namespace maquette {

struct Tiles3dExport {
  TerrainSettings terrain;
  // 3D content layers (kinds mesh, instances, volume; tiles3d/content_tile.h): a cell's content
  // becomes an additional content of its tile, OUTDIR/tiles/<LEVEL>/<CELL>.<LAYER>.glb (cells
  // without a terrain tile are skipped; coarser tiles get the layer's simplified copies).
  std::vector<std::string> content;
  RegionSpec region;
  int min_level = -1, max_level = -1;  // -1: the DEM's level, and 4 levels above it
};

// Returns the number of tiles written.
int64_t export_tiles3d(const Store& store, const Grid& grid, const Tiles3dExport& spec,
                       const std::string& out_dir);

}  // namespace maquette
