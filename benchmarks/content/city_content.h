// The content the content benchmarks write, made deterministically (fixed seeds, no state):
// - a town's trees: instances of the built-in prototypes, random but seeded positions, headings,
//   sizes and tints over a square of land, grouped by the cell holding each position;
// - a city's buildings: the Soho footprints (shared data, buildings/
//   london_soho_buildings_wgs84.geojson, 158 polygons) extruded as textured prisms and replicated
//   over a grid of copies side by side, grouped by the cell holding each footprint's first vertex.
// Each cell's content is in the east-north-up frame of the cell's centre (height 0).
#pragma once

#include <map>
#include <string>

#include "content/content.h"
#include "core/cell_id.h"

namespace maquette::bench {

struct TownSettings {
  size_t instances = 100'000;
  int level = 16;                      // ~140 m cells: a tile of trees a viewer loads at once
  double west = -0.32, south = 51.43;  // the square's south-west corner (degrees)
  double side_m = 4000;                // the square's side
  uint32_t seed = 1;
};
std::map<CellId, InstancesContent> town_trees(const TownSettings& settings = {});

struct CitySettings {
  size_t buildings = 20'000;
  int level = 15;        // ~280 m cells: a few dozen buildings per tile
  int copies_wide = 12;  // copies of the Soho block per row, west to east, then rows northwards
};
// Throws maquette::Error naming `geojson` when it cannot be read or holds a footprint that is
// not a simple polygon of at least 3 vertices.
std::map<CellId, MeshContent> city_buildings(const std::string& geojson,
                                             const CitySettings& settings = {});

// The footprints file in the shared data beside the repository.
std::string soho_footprints_path();

// Objects and triangles summed over cells.
ContentStats mesh_stats(const std::map<CellId, MeshContent>& cells);

}  // namespace maquette::bench
