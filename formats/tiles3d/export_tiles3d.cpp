#include "tiles3d/export_tiles3d.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>

#include "core/error.h"
#include "core/lonlat_bounds.h"
#include "gltf/cell_content.h"
#include "gltf/glb_merge.h"
#include "gltf/glb_writer.h"
#include "gltf/output_dir.h"
#include "tiles3d/tileset.h"

namespace maquette {
namespace {

constexpr double kEarthRadius = 6371008.8;

// The region of a cell's terrain: its vertices' bounds (a tile of a coarse level may hold data
// in a small part of its cell), padded sideways and in height by the quantization step (which
// moves vertices up to that far, in any direction), in latitude by the bulge of a straight edge
// towards the pole, and below by its sag under the ellipsoid's curve. Longitudes stay within
// [-pi, pi] with west <= east: a mesh across the antimeridian (a polar cell on the 180th meridian)
// gets every longitude, since not every viewer reads a region with west > east
// (3d-tiles-renderer does not); so does one reaching a pole, whose vertex there quantization
// moves to any longitude.
std::array<double, 6> cell_region(const CellTerrain& t, double spacing) {
  const TerrainMesh& mesh = t.mesh;
  const LonLatBounds& b = mesh.lonlat;
  constexpr double kPi = std::numbers::pi, rad = kPi / 180;
  const double max_abs_lat = std::min(89.0, std::max(std::abs(b.south), std::abs(b.north))) * rad;
  const double chord = spacing / kEarthRadius;
  const double dlat = t.lattice_step / kEarthRadius + chord * chord / 8 * std::tan(max_abs_lat);
  const double dlon = t.lattice_step / kEarthRadius / std::cos(max_abs_lat);
  const double south = std::max(-kPi / 2, b.south * rad - dlat);
  const double north = std::min(kPi / 2, b.north * rad + dlat);
  const bool all_longitudes =
      mesh.at_pole || b.west < -180 || b.east > 180 || south == -kPi / 2 || north == kPi / 2;
  const double west = all_longitudes ? -kPi : std::max(-kPi, b.west * rad - dlon);
  const double east = all_longitudes ? kPi : std::min(kPi, b.east * rad + dlon);
  const double sag = spacing * spacing / (8 * kEarthRadius);
  return {west,
          south,
          east,
          north,
          mesh.min_height - sag - t.lattice_step,
          mesh.max_height + t.lattice_step};
}

// A tile's files are OUTDIR/<stem>.glb and OUTDIR/<stem>.<LAYER>.glb.
std::string tile_stem(int level, CellId cell) {
  return "tiles/" + std::to_string(level) + "/" + cell.ToText();
}

std::pair<int, int> level_range(const Tiles3dExport& spec, const LayerInfo& dem) {
  const int hi = spec.max_level < 0 ? dem.level : spec.max_level;
  const int lo = spec.min_level < 0 ? std::max(0, hi - 4) : spec.min_level;
  if (lo > hi || hi > dem.level)
    throw Error("--levels " + std::to_string(lo) + ".." + std::to_string(hi) +
                ": expected A <= B <= " + std::to_string(dem.level) + " (the level of layer '" +
                dem.name + "')");
  return {lo, hi};
}

// Content is shown at the levels its layer holds (its own and the simplified copies at coarser
// ones): a tile finer than the layer's level would replace (REPLACE refinement) the tile holding
// the content with tiles holding none.
void require_content_levels(const Store& store, const std::string& layer, int finest) {
  require_content_layer(store, layer);
  const int level = store.require_layer(layer).level;
  if (finest > level)
    throw Error("content layer '" + layer + "' is at level " + std::to_string(level) +
                ", coarser than the finest tiles (level " + std::to_string(finest) +
                "): pass --levels A.." + std::to_string(level));
}

}  // namespace

int64_t export_tiles3d(const Store& store, const Grid& grid, const Tiles3dExport& spec,
                       const std::string& out_dir) {
  TerrainSource source(store, grid, spec.terrain);
  const auto [lo, hi] = level_range(spec, source.dem);
  for (const std::string& layer : spec.content) require_content_levels(store, layer, hi);
  const std::vector<CellId> tile_cells = layer_tile_cells(store, grid, source.dem, spec.region);
  std::map<int, std::vector<CellId>> cells;
  int64_t total = 0;
  for (int l = lo; l <= hi; ++l) {
    cells[l] = cells_at_level(tile_cells, l);
    total += int64_t(cells[l].size());
  }
  source.check_size(total, source.texture ? total : 0);
  prepare_output_dir(out_dir, spec.terrain.force);
  source.fit_texture_stretch(cells[lo]);
  const LocalFrame frame = frame_for(grid, tile_cells);  // the data's centre
  CellContentReader content_reader(store);

  // Level by level, finest first so that a parent's region can grow to hold its children's.
  // Meshes stream to their files, one per worker thread in memory; each cell's region is kept.
  std::map<CellId, std::unique_ptr<TileNode>> nodes;
  for (int l = hi; l >= lo; --l) {
    const double spacing = source.vertex_spacing(l);
    std::vector<std::optional<std::array<double, 6>>> regions(cells[l].size());
    for_each_terrain(source, frame, cells[l], [&](size_t i, CellTerrain&& t) {
      regions[i] = cell_region(t, spacing);
      const GlbPrimitive prim{&t.mesh, spec.terrain.draco ? &t.draco : nullptr,
                              t.image ? &*t.image : nullptr, t.cell.ToText()};
      write_file(inside(out_dir, tile_stem(l, t.cell) + ".glb").string(), make_glb({prim}));
    });
    for (size_t i = 0; i < cells[l].size(); ++i) {
      if (!regions[i]) continue;
      const CellId cell = cells[l][i];
      auto& node = nodes[cell];  // may exist already, holding children without a parent tile
      if (node)
        extend_region(node->region, *regions[i]);
      else
        node = std::make_unique<TileNode>(TileNode{cell, *regions[i], 0, {}, {}});
      node->geometric_error = l < hi ? spacing : 0;
      const std::string stem = tile_stem(l, cell);
      node->contents = {stem + ".glb"};
      for (const std::string& layer : spec.content) {
        const std::optional<CellGlb> content = content_reader.read(layer, cell);
        if (!content) continue;
        node->contents.push_back(stem + "." + layer + ".glb");
        // Placed in the export's frame by a node matrix around the GLB's own scene.
        const std::string name = layer + " " + cell.ToText();
        write_file(inside(out_dir, node->contents.back()).string(),
                   merge_glbs({{content->glb, frame_to_frame(content->origin, frame), name}},
                              nullptr, "content " + name));
        extend_region(node->region, content->region);
      }
    }
    // Children (level l) under their parents (level l - 1) when those exist.
    for (CellId c : cells[l]) {
      auto it = nodes.find(c);
      if (l == lo || it == nodes.end()) continue;
      // A parent without a DEM tile of its own still groups its children.
      auto& parent = nodes[c.parent()];
      if (!parent) {
        parent = std::make_unique<TileNode>(
            TileNode{c.parent(), it->second->region, source.vertex_spacing(l - 1), {}, {}});
      }
      extend_region(parent->region, it->second->region);
      parent->children.push_back(std::move(it->second));
      nodes.erase(it);
    }
  }
  if (nodes.empty()) throw Error("no terrain in the region: every DEM tile is nodata");
  std::vector<TileNode*> top;
  for (auto& [cell, node] : nodes) top.push_back(node.get());
  write_tilesets(out_dir, top, 2 * source.vertex_spacing(lo), frame.enu_to_ecef());
  return total;
}

}  // namespace maquette
