#include "gltf/export_glb.h"

#include <map>
#include <mutex>

#include "core/error.h"
#include "core/output_file.h"
#include "gltf/glb_writer.h"
#include "gltf/output_dir.h"

namespace maquette {
namespace {

// The cells level by level (each level has its own lattice).
std::map<int, std::vector<CellId>> by_level(const std::vector<CellId>& cells) {
  if (cells.empty()) throw Error("no cells given: pass --cells");
  std::map<int, std::vector<CellId>> out;
  for (CellId c : cells) out[c.level()].push_back(c);
  return out;
}

Error no_tiles(const TerrainSource& source) {
  return Error("layer '" + source.dem.name + "' has no tiles in the given cells");
}

}  // namespace

nlohmann::json frame_json(const LocalFrame& frame) {
  return {{"origin", {{"lon", frame.origin().lon}, {"lat", frame.origin().lat}, {"height", 0}}},
          {"axes", "x east, y up, z south (metres)"}};
}

void export_glb(const Store& store, const Grid& grid, const TerrainSettings& settings,
                const std::vector<CellId>& cells, const std::string& out) {
  TerrainSource source(store, grid, settings);
  source.check_size(int64_t(cells.size()), source.texture ? int64_t(cells.size()) : 0);
  source.fit_texture_stretch(cells);
  const LocalFrame frame = frame_for(grid, cells);
  std::vector<CellTerrain> terrain;  // one GLB of every cell: all meshes at once
  for (const auto& [level, group] : by_level(cells))
    for (auto& t : build_level(source, frame, group)) terrain.push_back(std::move(t));
  if (terrain.empty()) throw no_tiles(source);
  std::vector<GlbPrimitive> prims;
  for (const CellTerrain& t : terrain)
    prims.push_back({&t.mesh, settings.draco ? &t.draco : nullptr, t.image ? &*t.image : nullptr,
                     t.cell.ToText()});
  write_file(out, make_glb(prims, {{"maquette_frame", frame_json(frame)}}));
}

void export_drc(const Store& store, const Grid& grid, const TerrainSettings& settings,
                const std::vector<CellId>& cells, const std::string& out_dir) {
  const TerrainSource source(store, grid, settings);
  source.check_size(int64_t(cells.size()), 0);
  prepare_output_dir(out_dir, settings.force);
  const LocalFrame frame = frame_for(grid, cells);
  std::mutex offsets_lock;
  nlohmann::json offsets = nlohmann::json::object();  // where each cell's positions start from
  for (const auto& [level, group] : by_level(cells))
    for_each_terrain(source, frame, group, [&](size_t, CellTerrain&& t) {
      write_file(inside(out_dir, t.cell.ToText() + ".drc").string(), t.draco.data);
      const std::lock_guard lock(offsets_lock);
      offsets[t.cell.ToText()] = t.mesh.offset;
    });
  if (offsets.empty()) throw no_tiles(source);
  nlohmann::json frame_file = frame_json(frame);
  frame_file["offsets"] = offsets;
  write_file_whole(inside(out_dir, "frame.json").string(), frame_file.dump(2) + "\n");
}

}  // namespace maquette
