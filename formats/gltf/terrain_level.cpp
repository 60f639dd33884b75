#include "gltf/terrain_level.h"

#include <tbb/parallel_for.h>

#include <algorithm>

#include "core/error.h"
#include "core/lonlat_bounds.h"
#include "gltf/lattice.h"
#include "gltf/terrain_source.h"

namespace maquette {

TerrainSource::TerrainSource(const Store& store_, const Grid& grid_, TerrainSettings s)
    : store(store_),
      grid(grid_),
      settings(std::move(s)),
      dem(require_dem_layer(store, settings.dem)) {
  if (!settings.texture.empty()) texture = require_texture_layer(store, settings.texture);
  const int k = settings.decimation;
  if (k < 1 || k > dem.tile_size || dem.tile_size % k != 0)
    throw Error("--decimation " + std::to_string(k) + " must divide the tile size " +
                std::to_string(dem.tile_size));
  const QuantizationBits& b = settings.bits;
  if (b.position < 8 || b.position > 24 || b.texcoord < 6 || b.texcoord > 24 || b.normal < 6 ||
      b.normal > 24)
    throw Error("quantization bits out of range: positions 8..24, texcoords and normals 6..24");
}

double TerrainSource::vertex_spacing(int level) const {
  return grid.level_info(level, dem.tile_size).pixel_m * settings.decimation;
}

int64_t TerrainSource::check_size(int64_t tiles_total, int64_t tiles_with_texture) const {
  // About 3 bytes per Draco vertex and 0.4 bytes per imagery pixel, measured on smooth terrain.
  const int64_t vertices =
      int64_t(dem.tile_size / settings.decimation + 1) * (dem.tile_size / settings.decimation + 1);
  const int64_t pixels = texture ? int64_t(texture->tile_size) * texture->tile_size : 0;
  const int64_t bytes =
      tiles_total * vertices * (settings.draco ? 3 : 32) + tiles_with_texture * pixels * 2 / 5;
  if (bytes > settings.max_bytes && !settings.force)
    throw Error("the export would write about " + std::to_string(bytes >> 20) + " MiB in " +
                std::to_string(tiles_total) + " tiles, above the limit of " +
                std::to_string(settings.max_bytes >> 20) +
                " MiB: narrow --bbox/--levels, raise --decimation, or pass --force");
  return bytes;
}

LocalFrame frame_for(const Grid& grid, const std::vector<CellId>& cells) {
  const LonLatBounds b = lonlat_bounds(grid, cells);
  double lon = (b.west + b.east) / 2;
  if (lon >= 180) lon -= 360;
  return LocalFrame({lon, (b.south + b.north) / 2});
}

std::vector<CellTerrain> build_level(const TerrainSource& source, const LocalFrame& frame,
                                     const std::vector<CellId>& cells) {
  if (cells.empty()) return {};
  const int level = cells.front().level();
  const double skirt = 2 * source.vertex_spacing(level);
  std::vector<std::optional<CellTerrain>> built(cells.size());
  tbb::parallel_for(size_t(0), cells.size(), [&](size_t i) {
    const auto dem = dem_with_halo(source.store, source.grid, source.dem, cells[i]);
    if (!dem) return;
    CellTerrain t{
        cells[i],
        build_terrain_mesh(source.grid, cells[i], *dem, source.settings.decimation, frame, skirt),
        {},
        0,
        std::nullopt};
    if (t.mesh.indices.empty()) return;
    if (source.texture)
      if (const auto tex = texture_of(source.store, *source.texture, cells[i]))
        t.image = encode_texture(*tex);
    built[i] = std::move(t);
  });
  std::vector<CellTerrain> out;
  double max_extent = 0;
  for (auto& t : built)
    if (t) {
      max_extent = std::max(max_extent, extent(t->mesh.positions));
      out.push_back(std::move(*t));
    }
  // One lattice for the whole level, so shared edges decode identically.
  const Lattice lattice = Lattice::for_extent(max_extent, source.settings.bits.position);
  tbb::parallel_for(size_t(0), out.size(), [&](size_t i) {
    CellTerrain& t = out[i];
    const auto origin = lattice.origin(t.mesh.positions);
    lattice.snap(t.mesh.positions, origin);
    t.lattice_step = lattice.step;
    if (source.settings.draco)
      t.draco = encode_draco(t.mesh, lattice, origin, source.settings.bits);
  });
  return out;
}

}  // namespace maquette
