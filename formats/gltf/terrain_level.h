// Terrain of many cells of one level, built in parallel: meshes in the export's frame, snapped
// onto the level's lattice, Draco-encoded, with their imagery.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "gltf/draco_encode.h"
#include "gltf/local_frame.h"
#include "gltf/terrain_mesh.h"
#include "gltf/texture_image.h"
#include "image/stretch.h"
#include "store/store.h"

namespace maquette {

struct TerrainSettings {
  std::string dem;      // DEM layer
  std::string texture;  // imagery layer, "" for none
  int decimation = 1;   // a vertex every K pixels
  QuantizationBits bits;
  bool draco = true;                     // false: plain meshes (for comparisons)
  bool stretch = true;                   // the texture with the quicklooks' display stretch
  int64_t max_bytes = int64_t(4) << 30;  // refuse larger exports unless forced
  bool force = false;
};

// An export's inputs, checked: layers of the right kinds, a decimation dividing the tile size.
struct TerrainSource {
  TerrainSource(const Store& store, const Grid& grid, TerrainSettings settings);

  const Store& store;
  const Grid& grid;
  TerrainSettings settings;
  LayerInfo dem;
  std::optional<LayerInfo> texture;
  EllipsoidalHeights heights;  // the DEM's vertical datum to the ellipsoid

  // Distance between vertices at `level` (metres, mean).
  double vertex_spacing(int level) const;
  // Rough output size of `cells` tiles at `level`; throws (naming it) above max_bytes unless
  // forced.
  int64_t check_size(int64_t tiles_total, int64_t tiles_with_texture) const;

  // With settings.stretch, sets the texture's display stretch (image/stretch.h: 2-98 % of each
  // colour band, alpha left alone) from the texture of `cells`, e.g. an export's coarsest level:
  // the same look as `export png` of the imagery.
  void fit_texture_stretch(const std::vector<CellId>& cells);
  // A cell's texture as the export shows it: no-data texels padded (texture_image.h), stretched.
  Tile<uint8_t> displayed(Tile<uint8_t> texture) const;

 private:
  std::vector<StretchRange> stretch_;  // per colour band; empty: the values as stored
};

struct CellTerrain {
  CellId cell;
  TerrainMesh mesh;
  DracoPrimitive draco;     // empty without settings.draco
  double lattice_step = 0;  // positions moved up to this far (per axis, half of it) by quantization
  std::optional<EncodedImage> image;
};

// The export's frame: east-north-up at the centre of the cells' bounds.
LocalFrame frame_for(const Grid& grid, const std::vector<CellId>& cells);

// Receives the terrain of cells[index]; called from several threads at once (for different
// cells).
using TerrainSink = std::function<void(size_t index, CellTerrain&& terrain)>;

// Streams the terrain of `cells` (all at one level) to `sink`, one cell per worker thread in
// memory at a time; cells without a DEM tile are left out. The level's lattice depends on the
// widest mesh of the level, known only at the end: cells are built widest-looking first, each
// quantized on the lattice of the widest mesh seen so far, and the few cells whose lattice turns
// out too fine are built and handed to `sink` again, after all others. The last terrain `sink`
// receives for a cell is the one on the level's lattice (the same whatever the threads).
void for_each_terrain(const TerrainSource& source, const LocalFrame& frame,
                      const std::vector<CellId>& cells, const TerrainSink& sink);

// Terrain of `cells` (all at one level), in their order; cells without a DEM tile are left out.
std::vector<CellTerrain> build_level(const TerrainSource& source, const LocalFrame& frame,
                                     const std::vector<CellId>& cells);

}  // namespace maquette
