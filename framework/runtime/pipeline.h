// Pipelines: JSON in the spirit of PDAL pipelines, parsed and validated before anything runs.
//
//   {"store": "out/demo.mqt",
//    "region": {"bbox": [W, S, E, N]} | {"geojson": <GeoJSON or a file path>} | {"cells": ["N1"]},
//    "level": 8, "tile_size": 256,
//    "steps": [{"op": "terrain.derive", "inputs": {"dem": "dem"},
//               "outputs": {"slope": "slope"}, "params": {"z_factor": 1}},
//              {"op": "texture.procedural", "inputs": {"dem": "dem"},
//               "outputs": {"imagery": "texture"}, "refine": 2, "params": {...}}]}
//
// Relative paths resolve against the pipeline file's directory. Checks that need the store
// (input layers exist) are made by plan_run (run_plan.h).
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "core/cell_id.h"
#include "runtime/operator.h"
#include "runtime/operator_registry.h"

namespace maquette {

struct PipelineStep {
  int index = 0;  // 1-based, as in messages and run records
  std::string op_name;
  const Operator* op = nullptr;
  std::string module;  // "name version" of the operator's module, part of a run's identity
  std::map<std::string, std::string> inputs;   // port -> layer
  std::map<std::string, std::string> outputs;  // port -> layer (reduce: artifact name)
  nlohmann::json params;                       // validated, defaults filled in
  int refine = 0;  // outputs this many levels finer than the inputs (refinable cell, region ops)

  std::string label() const;  // "step 2 (terrain.derive)"
};

// The step's operator's check_params (OperatorSpec) on `params`, the step's params or those with
// their artifacts pasted in; its maquette::Error prefixed with the step's label.
void check_step_params(const PipelineStep& step, const nlohmann::json& params);

struct Pipeline {
  nlohmann::json document;  // the pipeline as written: part of the run's identity (--resume)
  std::string source;       // the file name, for messages
  std::string store_path;   // resolved
  std::string base_dir;     // the pipeline file's directory: relative paths resolve against it
  int level = 0;
  int tile_size = 256;
  std::vector<CellId> region;  // the region's cells at `level`, sorted by id
  std::vector<PipelineStep> steps;
};

// Reads and validates a pipeline file. Throws maquette::Error naming the file, step, field and
// value at fault (malformed JSON: with line and column).
Pipeline load_pipeline(const std::string& path, const OperatorRegistry& registry);
// The same from text; `source` names it in messages, `base_dir` resolves relative paths.
Pipeline parse_pipeline(std::string_view text, const std::string& source,
                        const std::string& base_dir, const OperatorRegistry& registry);

}  // namespace maquette
