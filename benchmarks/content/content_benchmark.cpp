// Writing 3D content into a store, per object: 100,000 tree instances over a town (level 16
// cells, instances_codec blobs) and 20,000 textured buildings over a city (the Soho footprints
// replicated, level 15 cells, mesh GLB blobs with Draco), as an operator's outputs would be.
// Encode: the blobs alone (CPU). Write: encode, then Batch::put_content into a fresh store file,
// one transaction per kCellsPerBatch cells, the file closed (wall time). Counters per object:
// time, blob bytes and store file bytes. The content is made once, outside the timings
// (city_content.h).
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <filesystem>

#include "city_content.h"
#include "content/content_blob.h"
#include "content/instances_codec.h"
#include "gltf/mesh_glb.h"
#include "store/store.h"

namespace maquette::bench {
namespace {

constexpr size_t kCellsPerBatch = 32;

const std::map<CellId, InstancesContent>& trees() {
  static const auto cells = town_trees();
  return cells;
}

const std::map<CellId, MeshContent>& buildings() {
  static const auto cells = city_buildings(soho_footprints_path());
  return cells;
}

std::string wrap_instances_blob(const InstancesContent& c) { return wrap_instances(c); }

// A store file in the temp directory, deleted (with its WAL) afterwards.
struct TempStore {
  TempStore(const std::string& layer, LayerKind kind, int level)
      : path((std::filesystem::temp_directory_path() /
              ("maquette-content-bench-" + std::to_string(::getpid()) + ".mqs"))
                 .string()) {
    remove();
    store = Store::open(path, Store::Mode::Create);
    LayerInfo l;
    l.name = layer;
    l.kind = kind;
    l.level = level;
    store->create_layer(l);
  }
  ~TempStore() { remove(); }
  void remove() {
    store.reset();
    for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(path + suffix);
  }
  std::string path;
  std::unique_ptr<Store> store;
};

void per_object_counters(benchmark::State& state, size_t cells, size_t objects, size_t blob_bytes,
                         size_t file_bytes) {
  const double n = double(objects);
  state.counters["cells"] = double(cells);
  state.counters["objects"] = n;
  state.counters["time_per_object"] = benchmark::Counter(
      n, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["blob_bytes_per_object"] = double(blob_bytes) / n;
  if (file_bytes) state.counters["file_bytes_per_object"] = double(file_bytes) / n;
}

template <class Content, class Wrap>
void encode(benchmark::State& state, const std::map<CellId, Content>& cells, size_t objects,
            Wrap wrap) {
  size_t bytes = 0;
  for (auto _ : state) {
    bytes = 0;
    for (const auto& [cell, content] : cells) bytes += wrap(content).size();
  }
  per_object_counters(state, cells.size(), objects, bytes, 0);
}

template <class Content, class Wrap>
void write(benchmark::State& state, const std::map<CellId, Content>& cells, size_t objects,
           LayerKind kind, int level, Wrap wrap) {
  size_t bytes = 0, file = 0;
  for (auto _ : state) {
    state.PauseTiming();
    TempStore t("content", kind, level);
    state.ResumeTiming();
    bytes = 0;
    auto cell = cells.begin();
    while (cell != cells.end()) {
      Store::Batch batch(*t.store);
      for (size_t k = 0; k < kCellsPerBatch && cell != cells.end(); ++k, ++cell) {
        const std::string blob = wrap(cell->second);
        bytes += blob.size();
        batch.put_content("content", cell->first, blob);
      }
      batch.commit();
    }
    t.store.reset();  // closed: WAL checkpointed into the file
    state.PauseTiming();
    file = std::filesystem::file_size(t.path);
    state.ResumeTiming();
  }
  per_object_counters(state, cells.size(), objects, bytes, file);
}

size_t instance_count() {
  size_t n = 0;
  for (const auto& [cell, c] : trees()) n += c.size();
  return n;
}

void BM_InstancesEncode(benchmark::State& state) {
  encode(state, trees(), instance_count(), wrap_instances_blob);
}
void BM_InstancesWrite(benchmark::State& state) {
  write(state, trees(), instance_count(), LayerKind::Instances, TownSettings{}.level,
        wrap_instances_blob);
}
void BM_MeshesEncode(benchmark::State& state) {
  encode(state, buildings(), mesh_stats(buildings()).objects, mesh_content_blob);
}
void BM_MeshesWrite(benchmark::State& state) {
  write(state, buildings(), mesh_stats(buildings()).objects, LayerKind::Mesh, CitySettings{}.level,
        mesh_content_blob);
}

BENCHMARK(BM_InstancesEncode)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_InstancesWrite)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_MeshesEncode)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MeshesWrite)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace maquette::bench

BENCHMARK_MAIN();
