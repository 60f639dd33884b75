// The pipelines of examples/ run by tests from their own temporary folders.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace maquette::test {

// A JSON file, parsed.
nlohmann::json read_json(const std::string& path);

// examples/NAME.json (MAQUETTE_SOURCE_DIR) with the sources of its ingest steps as absolute
// paths: ../../shared/... in the shared data (MAQUETTE_SHARED_DIR), other paths in examples/.
nlohmann::json example_pipeline(const std::string& name);

}  // namespace maquette::test
