// Writes content_benchmark's town and city as stores for export_timing.sh: DIR/town.maquette
// (layer `trees`: 100,000 instances at level 16) and DIR/city.maquette (layer `buildings`:
// 20,000 textured buildings at level 15), each with a flat DEM `dem` (16 x 16 zeros) in the
// content's cells, which `export tiles3d` requires; prints per layer its objects and level.
// Not a Google Benchmark: the export it feeds is a separate program, timed by the script.
#include <filesystem>
#include <iostream>
#include <map>

#include "city_content.h"
#include "content/instances_codec.h"
#include "gltf/mesh_glb.h"
#include "store/store.h"

namespace {

using namespace maquette;

template <class Content, class Wrap>
void write_store(const std::string& path, const std::string& layer, LayerKind kind, int level,
                 const std::map<CellId, Content>& cells, Wrap wrap) {
  for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(path + suffix);
  auto store = Store::open(path, Store::Mode::Create);
  LayerInfo l;
  l.name = layer;
  l.kind = kind;
  l.level = level;
  store->create_layer(l);
  LayerInfo dem;
  dem.name = "dem";
  dem.tile_size = 16;
  dem.level = level;
  dem.units = "m";
  store->create_layer(dem);
  const RawTile flat{DType::F32, 16, 1, std::vector<std::byte>(16 * 16 * 4)};
  Store::Batch batch(*store);
  for (const auto& [cell, content] : cells) {
    batch.put_content(layer, cell, wrap(content));
    batch.put_tile("dem", cell, flat);
  }
  batch.commit();
}

}  // namespace

int main(int argc, char** argv) try {
  if (argc != 2) {
    std::cerr << "usage: content_stores DIR\n";
    return 2;
  }
  const std::string dir = argv[1];
  std::filesystem::create_directories(dir);
  const bench::TownSettings town;
  const bench::CitySettings city;
  const auto trees = bench::town_trees(town);
  const auto buildings = bench::city_buildings(bench::soho_footprints_path(), city);
  write_store(dir + "/town.maquette", "trees", LayerKind::Instances, town.level, trees,
              [](const InstancesContent& c) { return wrap_instances(c); });
  write_store(dir + "/city.maquette", "buildings", LayerKind::Mesh, city.level, buildings,
              [](const MeshContent& c) { return mesh_content_blob(c); });
  std::cout << nlohmann::json{{"trees", {{"objects", town.instances}, {"level", town.level}}},
                              {"buildings",
                               {{"objects", bench::mesh_stats(buildings).objects},
                                {"level", city.level}}}}
            << "\n";
  return 0;
} catch (const std::exception& e) {
  std::cerr << "content_stores: " << e.what() << "\n";
  return 1;
}
