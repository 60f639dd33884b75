#include "gltf/export_glb.h"

#include <map>
#include <mutex>

#include "core/error.h"
#include "core/output_file.h"
#include "gltf/cell_content.h"
#include "gltf/glb_merge.h"
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

constexpr std::array<double, 16> kIdentity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

Error no_tiles(const TerrainSource& source) {
  return Error("layer '" + source.dem.name + "' has no tiles in the given cells");
}

// The terrain of `cells` as one GLB in `frame`, a mesh per cell.
std::vector<char> terrain_glb(const Store& store, const Grid& grid, const TerrainSettings& settings,
                              const std::vector<CellId>& cells, const LocalFrame& frame) {
  TerrainSource source(store, grid, settings);
  source.check_size(int64_t(cells.size()), source.texture ? int64_t(cells.size()) : 0);
  source.fit_texture_stretch(cells);
  std::vector<CellTerrain> terrain;  // one GLB of every cell: all meshes at once
  for (const auto& [level, group] : by_level(cells))
    for (auto& t : build_level(source, frame, group)) terrain.push_back(std::move(t));
  if (terrain.empty()) throw no_tiles(source);
  std::vector<GlbPrimitive> prims;
  for (const CellTerrain& t : terrain)
    prims.push_back({&t.mesh, settings.draco ? &t.draco : nullptr, t.image ? &*t.image : nullptr,
                     t.cell.ToText()});
  return make_glb(prims, {{"maquette_frame", frame_json(frame)}});
}

}  // namespace

nlohmann::json frame_json(const LocalFrame& frame) {
  return {{"origin", {{"lon", frame.origin().lon}, {"lat", frame.origin().lat}, {"height", 0}}},
          {"axes", "x east, y up, z south (metres)"}};
}

void export_glb(const Store& store, const Grid& grid, const GlbExport& spec,
                const std::vector<CellId>& cells, const std::string& out) {
  if (spec.terrain.dem.empty() && spec.content.empty())
    throw Error("nothing to export: pass --dem, --content or both");
  by_level(cells);  // refuses an empty list
  for (const std::string& layer : spec.content) require_content_layer(store, layer);
  const LocalFrame frame = frame_for(grid, cells);
  std::vector<char> terrain;
  if (!spec.terrain.dem.empty()) terrain = terrain_glb(store, grid, spec.terrain, cells, frame);
  if (spec.content.empty()) return write_file(out, terrain);

  CellContentReader reader(store);
  std::vector<std::pair<std::string, CellGlb>> contents;  // by layer, then cell
  for (const std::string& layer : spec.content)
    for (CellId cell : cells)
      if (auto c = reader.read(layer, cell)) contents.emplace_back(layer + " " + cell.ToText(), *c);
  std::vector<GlbPart> parts;
  if (!terrain.empty()) parts.push_back({{terrain.data(), terrain.size()}, kIdentity, "terrain"});
  for (const auto& [name, c] : contents)
    parts.push_back({c.glb, frame_to_frame(c.origin, frame), name});
  if (parts.empty()) throw Error("the given cells hold no content of the layers given");
  write_file(out, merge_glbs(parts, {{"maquette_frame", frame_json(frame)}}, "export glb " + out));
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
