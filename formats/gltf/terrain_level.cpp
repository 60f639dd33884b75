#include "gltf/terrain_level.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <functional>
#include <numeric>
#include <tuple>

#include "core/error.h"
#include "core/lonlat_bounds.h"
#include "gltf/lattice.h"
#include "gltf/terrain_source.h"
#include "image/option_layers.h"

namespace maquette {

TerrainSource::TerrainSource(const Store& store_, const Grid& grid_, TerrainSettings s)
    : store(store_),
      grid(grid_),
      settings(std::move(s)),
      dem(height_layer(store, settings.dem)),
      heights(ellipsoidal_heights(dem)) {
  if (!settings.texture.empty()) texture = require_texture_layer(store, settings.texture);
  const int k = settings.decimation;
  if (k < 1 || k > dem.tile_size || dem.tile_size % k != 0)
    throw Error("--decimation " + std::to_string(k) + " must divide the tile size " +
                std::to_string(dem.tile_size));
  const QuantizationBits& b = settings.bits;
  // Draco quantizes in float, rounding (value - min) / step + 0.5: exact only below 2^23 steps,
  // beyond which vertices shared by two tiles may decode apart.
  for (const auto& [option, value, low, high] : {std::tuple{"--position-bits", b.position, 8, 23},
                                                 std::tuple{"--texcoord-bits", b.texcoord, 6, 24},
                                                 std::tuple{"--normal-bits", b.normal, 6, 24}})
    if (value < low || value > high)
      throw Error(std::string(option) + " " + std::to_string(value) + " is out of range " +
                  std::to_string(low) + ".." + std::to_string(high));
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

void TerrainSource::fit_texture_stretch(const std::vector<CellId>& cells) {
  if (!texture || !settings.stretch) return;
  const int bands = texture->channels == 4 ? 3 : texture->channels;
  std::vector<std::vector<float>> values(static_cast<size_t>(bands));
  for (CellId c : cells) {
    const auto tile = texture_of(store, *texture, c);
    if (!tile) continue;
    for (int r = 0; r < tile->size(); ++r)
      for (int col = 0; col < tile->size(); ++col)
        for (int k = 0; k < bands; ++k)
          if (const uint8_t v = tile->at(col, r, k); !texture->nodata || v != *texture->nodata)
            values[size_t(k)].push_back(v);
  }
  stretch_.clear();
  for (auto& v : values)
    stretch_.push_back(quantile_range(v, kDisplayStretch.first, kDisplayStretch.second));
}

Tile<uint8_t> TerrainSource::displayed(Tile<uint8_t> tile) const {
  if (const auto nodata = texture->nodata; nodata && *nodata >= 0 && *nodata <= 255)
    pad_no_data(tile, uint8_t(*nodata));
  for (int r = 0; r < tile.size(); ++r)
    for (int c = 0; c < tile.size(); ++c)
      for (size_t k = 0; k < stretch_.size(); ++k)
        tile.at(c, r, int(k)) = stretch_byte(tile.at(c, r, int(k)), stretch_[k]);
  return tile;
}

LocalFrame frame_for(const Grid& grid, const std::vector<CellId>& cells) {
  const LonLatBounds b = lonlat_bounds(grid, cells);
  double lon = (b.west + b.east) / 2;
  if (lon >= 180) lon -= 360;
  return LocalFrame({lon, (b.south + b.north) / 2});
}

namespace {

// The mesh of `cell` in the export's frame, not yet quantized, with its imagery; nullopt without
// a DEM tile or without any triangle.
std::optional<CellTerrain> mesh_cell(const TerrainSource& source, const LocalFrame& frame,
                                     CellId cell, double skirt) {
  const auto dem = dem_with_halo(source.store, source.grid, source.dem, cell);
  if (!dem) return std::nullopt;
  CellTerrain t{cell,
                build_terrain_mesh(source.grid, cell, *dem, source.settings.decimation, frame,
                                   skirt, source.heights),
                {},
                0,
                std::nullopt};
  if (t.mesh.indices.empty()) return std::nullopt;
  if (source.texture)
    if (const auto tex = texture_of(source.store, *source.texture, cell))
      t.image = encode_texture(source.displayed(*tex));
  return t;
}

// Snaps the mesh onto `lattice`, measured from its offset, and encodes it.
void quantize(CellTerrain& t, const Lattice& lattice, const TerrainSettings& settings) {
  lattice.rebase(t.mesh);
  t.lattice_step = lattice.step;
  if (settings.draco) t.draco = encode_draco(t.mesh, lattice, settings.bits);
}

// A cheap guess of the extent of `cell`'s mesh: that of its boundary at height 0 (meshes differ
// mostly by their cell's shape and its tilt in the frame).
double guessed_extent(const Grid& grid, const LocalFrame& frame, CellId cell) {
  std::vector<double> ring;
  for (const LonLat& p : grid.boundary(cell, 2)) {
    const Vec3 v = frame.to_gltf(p, 0);
    ring.insert(ring.end(), v.begin(), v.end());
  }
  return extent(ring);
}

// Runs work(0), ..., work(n - 1) on every worker thread, each taking the next index when done:
// one item per thread in flight, started in index order. The first exception stops the others
// from taking more and is rethrown.
void for_each_index(size_t n, const std::function<void(size_t)>& work) {
  std::atomic<size_t> next = 0;
  tbb::parallel_for(0, tbb::this_task_arena::max_concurrency(), [&](int) {
    for (size_t i = next++; i < n; i = next++) {
      try {
        work(i);
      } catch (...) {
        next = n;
        throw;
      }
    }
  });
}

}  // namespace

void for_each_terrain(const TerrainSource& source, const LocalFrame& frame,
                      const std::vector<CellId>& cells, const TerrainSink& sink) {
  if (cells.empty()) return;
  const double skirt = 2 * source.vertex_spacing(cells.front().level());
  const int bits = source.settings.bits.position;
  std::vector<double> extents(cells.size(), 0);  // of each mesh, 0 without terrain
  std::vector<double> steps(cells.size(), 0);    // of the lattice each cell was quantized on
  std::atomic<double> widest = 0;                // the widest mesh seen so far
  // The widest-looking cells first, so that few cells are quantized on a lattice that turns out
  // too fine.
  std::vector<double> guesses(cells.size());
  for (size_t i = 0; i < cells.size(); ++i)
    guesses[i] = guessed_extent(source.grid, frame, cells[i]);
  std::vector<size_t> order(cells.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::ranges::stable_sort(order, std::greater{}, [&](size_t i) { return guesses[i]; });
  for_each_index(cells.size(), [&](size_t k) {
    const size_t i = order[k];
    auto t = mesh_cell(source, frame, cells[i], skirt);
    if (!t) return;
    extents[i] = extent(t->mesh.positions);
    double w = widest.load();
    while (w < extents[i] && !widest.compare_exchange_weak(w, extents[i])) {
    }
    const Lattice lattice = Lattice::for_extent(std::max(w, extents[i]), bits);
    steps[i] = lattice.step;
    quantize(*t, lattice, source.settings);
    sink(i, std::move(*t));
  });
  // One lattice for the whole level, so shared edges decode identically.
  const Lattice lattice = Lattice::for_extent(*std::ranges::max_element(extents), bits);
  std::vector<size_t> stale;
  for (size_t i = 0; i < cells.size(); ++i)
    if (steps[i] != 0 && steps[i] != lattice.step) stale.push_back(i);
  for_each_index(stale.size(), [&](size_t k) {
    auto t = mesh_cell(source, frame, cells[stale[k]], skirt);  // as the first time
    quantize(*t, lattice, source.settings);
    sink(stale[k], std::move(*t));
  });
}

std::vector<CellTerrain> build_level(const TerrainSource& source, const LocalFrame& frame,
                                     const std::vector<CellId>& cells) {
  std::vector<std::optional<CellTerrain>> built(cells.size());
  for_each_terrain(source, frame, cells,
                   [&](size_t i, CellTerrain&& t) { built[i] = std::move(t); });
  std::vector<CellTerrain> out;
  for (auto& t : built)
    if (t) out.push_back(std::move(*t));
  return out;
}

}  // namespace maquette
