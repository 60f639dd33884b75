// Helpers of the runtime tests: the fixture modules, temporary directories, pipelines, and
// snapshots of a store's tiles and artifacts for bit-exact comparisons.
#pragma once

#include <cstddef>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "runtime/operator_registry.h"
#include "runtime/pipeline.h"

namespace maquette::test {

std::string fixture_dir(const std::string& name);  // test_modules/<name>
const OperatorRegistry& fixture_registry();        // the operators of test_modules/good

class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::string& path() const { return path_; }
  std::string file(const std::string& name) const { return path_ + "/" + name; }

 private:
  std::string path_;
};

// fill(seed) -> height; blur(height) -> smooth; sum(smooth) -> smooth_sum; region_scan(smooth) ->
// scan, over the cells of `region` at level 4 (Q2: 64 cells), 16-pixel tiles, store "out.mqt".
// The number of distinct threads that ran fixture.fill or fixture.blur since the last reset.
size_t fixture_threads();
void reset_fixture_threads();

nlohmann::json demo_pipeline(int fill_sleep_ms = 0, int blur_sleep_ms = 0,
                             const std::string& blur_fail_on = "",
                             const nlohmann::json& cells = {"Q2"});

// Writes `doc` as DIR/pipeline.json and loads it with the fixture registry.
std::string write_pipeline(const TempDir& dir, const nlohmann::json& doc);
Pipeline load_fixture_pipeline(const std::string& path);

// "layer/cell" -> tile bytes for every tile, "layer/overview/cell" -> bytes for every overview
// tile, "layer/content/cell" -> the blob of every content cell (any level), "artifact/name" ->
// data for every artifact.
using Snapshot = std::map<std::string, std::vector<std::byte>>;
Snapshot snapshot(const std::string& store_path);
// The first key where the snapshots differ, or "" when they are equal.
std::string first_difference(const Snapshot& a, const Snapshot& b);

// The status of every run record of a store, by run id ("running", "ok", "failed: ...").
std::vector<std::string> run_statuses(const std::string& store_path);

// The message of the maquette::Error `f` throws ("" if none).
template <typename F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace maquette::test
