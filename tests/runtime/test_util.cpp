#include "test_util.h"

#include <dlfcn.h>
#include <sqlite3.h>
#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <span>
#include <stdexcept>

#include "store/store.h"

namespace maquette::test {

std::string fixture_dir(const std::string& name) {
  return std::string(MAQUETTE_FIXTURE_MODULE_DIR) + "/" + name;
}

const OperatorRegistry& fixture_registry() {
  static const OperatorRegistry registry = OperatorRegistry::load({fixture_dir("good")});
  return registry;
}

// A C entry point of the fixture module (already loaded by fixture_registry()).
template <typename F>
F* fixture_function(const char* name) {
  fixture_registry();
  void* module =
      dlopen((fixture_dir("good") + "/libfixture_ops.so").c_str(), RTLD_NOW | RTLD_NOLOAD);
  if (module == nullptr) throw std::runtime_error("the fixture module is not loaded");
  return reinterpret_cast<F*>(dlsym(module, name));
}

size_t fixture_threads() { return fixture_function<size_t()>("fixture_thread_count")(); }
void reset_fixture_threads() { fixture_function<void()>("fixture_reset_threads")(); }

TempDir::TempDir() {
  std::string templ = (std::filesystem::temp_directory_path() / "maquette_runtime_XXXXXX").string();
  path_ = mkdtemp(templ.data());
}

TempDir::~TempDir() { std::filesystem::remove_all(path_); }

nlohmann::json demo_pipeline(int fill_sleep_ms, int blur_sleep_ms, const std::string& blur_fail_on,
                             const nlohmann::json& cells) {
  using nlohmann::json;
  return {{"store", "out.mqt"},
          {"region", {{"cells", cells}}},
          {"level", 4},
          {"tile_size", 16},
          {"steps",
           {{{"op", "fixture.fill"},
             {"outputs", {{"value", "height"}}},
             {"params", {{"seed", 1.5}, {"sleep_ms", fill_sleep_ms}}}},
            {{"op", "fixture.blur"},
             {"inputs", {{"src", "height"}}},
             {"outputs", {{"dst", "smooth"}}},
             {"params", {{"sleep_ms", blur_sleep_ms}, {"fail_on", blur_fail_on}}}},
            {{"op", "fixture.sum"},
             {"inputs", {{"src", "smooth"}}},
             {"outputs", {{"total", "smooth_sum"}}}},
            {{"op", "fixture.region_scan"},
             {"inputs", {{"src", "smooth"}}},
             {"outputs", {{"dst", "scan"}}}}}}};
}

std::string write_pipeline(const TempDir& dir, const nlohmann::json& doc) {
  const std::string path = dir.file("pipeline.json");
  std::ofstream(path) << doc.dump(2);
  return path;
}

Pipeline load_fixture_pipeline(const std::string& path) {
  return load_pipeline(path, fixture_registry());
}

Snapshot snapshot(const std::string& store_path) {
  Snapshot out;
  const auto store = Store::open(store_path, Store::Mode::ReadOnly);
  for (const LayerInfo& layer : store->layers()) {
    if (layer_content_kind(layer.kind)) {  // content blobs at every level that holds some
      for (int level = layer.level; level >= 0; --level)
        for (const CellId cell : store->content_cells(layer.name, level)) {
          const std::string blob = *store->get_content(layer.name, cell);
          const auto bytes = std::as_bytes(std::span(blob));
          out[layer.name + "/content/" + cell.ToText()].assign(bytes.begin(), bytes.end());
        }
      continue;
    }
    for (const CellId cell : store->tile_cells(layer.name)) {
      out[layer.name + "/" + cell.ToText()] = store->get_tile(layer.name, cell)->bytes;
      // The overview tiles: every ancestor of a tile, down to level 0.
      for (int level = layer.level - 1; level >= 0; --level) {
        const CellId parent = cell.parent(level);
        if (out.count(layer.name + "/overview/" + parent.ToText())) break;  // seen from a sibling
        if (const auto tile = store->get_overview(layer.name, parent))
          out[layer.name + "/overview/" + parent.ToText()] = tile->bytes;
      }
    }
  }
  for (const std::string& name : store->artifact_names())
    out["artifact/" + name] = store->get_artifact(name)->data;
  return out;
}

std::vector<std::string> run_statuses(const std::string& store_path) {
  sqlite3* db = nullptr;
  sqlite3_open_v2(store_path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr);
  sqlite3_stmt* q = nullptr;
  sqlite3_prepare_v2(db, "SELECT status FROM runs ORDER BY id", -1, &q, nullptr);
  std::vector<std::string> out;
  while (sqlite3_step(q) == SQLITE_ROW)
    out.emplace_back(reinterpret_cast<const char*>(sqlite3_column_text(q, 0)));
  sqlite3_finalize(q);
  sqlite3_close(db);
  return out;
}

std::string first_difference(const Snapshot& a, const Snapshot& b) {
  for (const auto& [key, bytes] : a) {
    const auto it = b.find(key);
    if (it == b.end()) return key + " (missing in the second)";
    if (it->second != bytes) return key;
  }
  for (const auto& [key, bytes] : b)
    if (!a.count(key)) return key + " (missing in the first)";
  return "";
}

}  // namespace maquette::test
