// 3D Tiles 1.1 tileset.json files for a cell tree: `region` bounding volumes (radians, heights
// in metres), REPLACE refinement, the ENU -> ECEF transform on the root; a tile with several
// contents (terrain and 3D content layers) lists them in `contents` (3D Tiles 1.1). Every tile
// kSubtreeDepth levels below the top tiles (and so on) roots an external tileset
// (subtrees/<CELL>.json), so no JSON file holds more than 4^kSubtreeDepth tiles per top tile.
#pragma once

#include <array>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "core/cell_id.h"

namespace maquette {

inline constexpr int kSubtreeDepth = 4;

struct TileNode {
  CellId cell;
  std::array<double, 6> region{};  // west, south, east, north (radians), min, max height (m)
  double geometric_error = 0;
  std::vector<std::string> contents;  // relative uris of the .glb files (terrain first)
  std::vector<std::unique_ptr<TileNode>> children;
};

// Grows a region to hold another one.
void extend_region(std::array<double, 6>& region, const std::array<double, 6>& other);

// Writes OUTDIR/tileset.json (a root tile over `top`, with `transform`; it has no content, so its
// geometric error is at least the size of its region) and the external tilesets under
// OUTDIR/subtrees.
void write_tilesets(const std::filesystem::path& out_dir, const std::vector<TileNode*>& top,
                    double root_error, const std::array<double, 16>& transform);

}  // namespace maquette
