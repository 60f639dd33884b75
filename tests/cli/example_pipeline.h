// The pipelines of examples/ run by tests from their own temporary folders.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace maquette::test {

// The shared data (../shared beside the repository) and the examples' folder.
inline const std::string kShared = MAQUETTE_SHARED_DIR;
inline const std::string kExamples = std::string(MAQUETTE_SOURCE_DIR) + "/examples";

// A JSON file, parsed.
nlohmann::json read_json(const std::string& path);

// examples/NAME.json with the sources of its ingest steps as absolute paths: ../../shared/... in
// the shared data, other paths in examples/.
nlohmann::json example_pipeline(const std::string& name);

}  // namespace maquette::test
