// The program's built-in pipeline steps, tasks (runtime/task_operator.h) of the module
// "maquette": `ingest` (step_ingest.cpp) and `export` (step_export.cpp), which take the options of
// `maquette ingest` and `maquette export` as params and call the same functions.
#pragma once

#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "runtime/operator_registry.h"

namespace maquette::cli {

std::unique_ptr<Operator> make_ingest_step();
std::unique_ptr<Operator> make_export_step();

// The loaded modules and the built-in steps, loaded on first use.
const OperatorRegistry& program_registry();

// `path` resolved against the pipeline file's directory `base_dir` (absolute paths unchanged).
std::string resolve_path(const std::string& base_dir, const std::string& path);

// The JSON Schema of a step param: an array of `item_type` ("string", "number"...).
nlohmann::json array_schema(const char* item_type, const std::string& description);

// params[key] into `into` when present (params are validated against the step's schema).
template <typename T>
void read_param(const nlohmann::json& params, const char* key, T& into) {
  if (params.contains(key)) into = params.at(key).get<T>();
}

}  // namespace maquette::cli
