#include "gltf/export_glb.h"

#include <fstream>
#include <map>

#include "core/error.h"
#include "gltf/glb_writer.h"
#include "gltf/output_dir.h"

namespace maquette {
namespace {

// The terrain of every cell, level by level (each level has its own lattice).
std::vector<CellTerrain> build_cells(const TerrainSource& source, const LocalFrame& frame,
                                     const std::vector<CellId>& cells) {
  if (cells.empty()) throw Error("no cells given: pass --cells");
  std::map<int, std::vector<CellId>> by_level;
  for (CellId c : cells) by_level[c.level()].push_back(c);
  std::vector<CellTerrain> out;
  for (const auto& [level, group] : by_level) {
    auto built = build_level(source, frame, group);
    for (auto& t : built) out.push_back(std::move(t));
  }
  if (out.empty()) throw Error("layer '" + source.dem.name + "' has no tiles in the given cells");
  return out;
}

}  // namespace

nlohmann::json frame_json(const LocalFrame& frame) {
  return {{"origin", {{"lon", frame.origin().lon}, {"lat", frame.origin().lat}, {"height", 0}}},
          {"axes", "x east, y up, z south (metres)"}};
}

void export_glb(const Store& store, const Grid& grid, const TerrainSettings& settings,
                const std::vector<CellId>& cells, const std::string& out) {
  const TerrainSource source(store, grid, settings);
  source.check_size(int64_t(cells.size()), source.texture ? int64_t(cells.size()) : 0);
  const LocalFrame frame = frame_for(grid, cells);
  const std::vector<CellTerrain> terrain = build_cells(source, frame, cells);
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
  for (const CellTerrain& t : build_cells(source, frame, cells))
    write_file(inside(out_dir, t.cell.ToText() + ".drc").string(), t.draco.data);
  std::ofstream(inside(out_dir, "frame.json")) << frame_json(frame).dump(2) << "\n";
}

}  // namespace maquette
