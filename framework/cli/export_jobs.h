// One export, as `maquette export` options or an `export` pipeline step's params describe it.
#pragma once

#include <string>
#include <vector>

#include "geotiff/export_geotiff.h"
#include "gltf/terrain_level.h"
#include "image/layer_cells.h"
#include "tiles3d/export_tiles3d.h"
#include "vector/export_features.h"

namespace maquette::cli {

struct RegionOptions {
  std::vector<double> bbox;        // W S E N, or empty
  std::vector<std::string> cells;  // text ids
};

struct GtiffJob {
  std::string store, out;
  RegionOptions region;
  GeoTiffExport spec;
};

struct PngJob {
  std::string store, layer, out, ramp, projection = "auto";
  std::string overlay;  // features layer drawn over the picture, or ""
  RegionOptions region;
  std::vector<double> range;  // empty or 2
  std::vector<int> bands;     // 1-based
  bool hillshade = false;
  bool legend = true;
  int max_size = 2048;
};

struct FeaturesJob {  // geojson, gpkg
  std::string store, layer, out;
  RegionOptions region;
  FeatureFormat format = FeatureFormat::GeoJson;
};

struct Tiles3dJob {
  std::string store, out, levels;  // levels: "A..B" or ""
  RegionOptions region;
  Tiles3dExport spec;
};

struct MeshJob {  // glb, drc
  std::string store, out;
  std::vector<std::string> cells;
  TerrainSettings terrain;           // glb: terrain.dem empty for content only
  std::vector<std::string> content;  // glb only: 3D content layers
};

// Each writes its files, then logs them. Throws maquette::Error.
void run_export(GtiffJob job);
void run_export(const PngJob& job);
void run_export(const FeaturesJob& job);
void run_export(Tiles3dJob job);
void run_glb_export(const MeshJob& job);
void run_drc_export(const MeshJob& job);

}  // namespace maquette::cli
