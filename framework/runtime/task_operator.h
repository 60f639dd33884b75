// Tasks: steps run once, as a whole, by the first process of a run, outside the cell machinery.
// The program's built-in steps are tasks: `ingest` (sources into a layer) and `export` (layers
// out of the store), so that a pipeline goes from source files to viewer files. Their params are
// validated against their schema like an operator's; plan() tells, before anything runs, what a
// task reads and writes, so that the steps after it are planned and checked as usual.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "runtime/operator.h"

namespace maquette {

struct TaskContext {
  std::string store_path;
  std::string base_dir;          // the pipeline file's directory: relative paths resolve here
  const json* params = nullptr;  // validated, defaults filled in
  const std::map<std::string, std::string>* outputs = nullptr;  // port -> layer, as in the step
  int threads = 0;                                              // the run's worker threads
  bool resume = false;  // the run resumes: a task may finish its own interrupted work
  bool quiet = false;
};

struct TaskPlan {
  std::vector<std::pair<std::string, std::string>> reads;  // (params field, layer) read
  std::optional<LayerInfo> layer;  // the raster layer written, created before anything runs
  std::vector<CellId> cells;       // its tiles (sorted; those without data are not written)
  std::string written;             // another layer or artifact written (features, stations)
};

class TaskOperator : public Operator {
 public:
  // Reads what it needs (source files, the store) but writes nothing. Throws maquette::Error.
  virtual TaskPlan plan(const TaskContext& ctx) const = 0;
  virtual void run(const TaskContext& ctx) const = 0;
};

}  // namespace maquette
