// The tests' and benchmark's real footprints: London Soho's 158 OSM buildings (read with GDAL)
// on a synthetic DEM, each with the site structures.buildings gives it (its cell at kSohoLevel,
// that cell's DEM tile with the operator's halo, the content frame at the cell's centre).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "../building_mesh.h"

namespace maquette::structures {

inline constexpr int kSohoLevel = 14;      // cells of ~560 m (rHEALPix halves them per level)
inline constexpr int kSohoTileSize = 256;  // ~2.2 m pixels

// Terrain as a function of the grid's plane (metres): slopes of up to 2 % and waves of a few
// metres, so that the lowest point under a footprint is anywhere in it.
double soho_terrain(const PlanePoint& p);

struct SohoScene {
  std::vector<VectorFeature> footprints;
  std::map<CellId, Tile<float>> dems;  // each pixel the terrain at its centre

  // Reads the GeoJSON at `path`; throws std::runtime_error when GDAL cannot open it.
  explicit SohoScene(const std::string& path);
  BuildingSite site(const VectorFeature& footprint) const;
};

}  // namespace maquette::structures
