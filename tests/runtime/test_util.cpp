#include "test_util.h"

#include <stdlib.h>

#include <filesystem>
#include <fstream>

#include "store/store.h"

namespace maquette::test {

std::string fixture_dir(const std::string& name) {
  return std::string(MAQUETTE_FIXTURE_MODULE_DIR) + "/" + name;
}

const OperatorRegistry& fixture_registry() {
  static const OperatorRegistry registry = OperatorRegistry::load({fixture_dir("good")});
  return registry;
}

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
  for (const LayerInfo& layer : store->layers())
    for (const CellId cell : store->tile_cells(layer.name))
      out[layer.name + "/" + cell.ToText()] = store->get_tile(layer.name, cell)->bytes;
  for (const std::string& name : store->artifact_names())
    out["artifact/" + name] = store->get_artifact(name)->data;
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
