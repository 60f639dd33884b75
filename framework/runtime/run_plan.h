// What a run will do, worked out before anything runs: for each step the layers it reads and
// writes (checked against the store and the earlier steps) and the cells it processes.
#pragma once

#include <cstdint>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "runtime/cell_plan.h"
#include "runtime/pipeline.h"
#include "runtime/task_operator.h"
#include "store/store.h"

namespace maquette {

// A region step's square mosaic: the bounding box of its cells on their face, `cells` cells a
// side from cell (col0, row0).
struct MosaicBox {
  uint32_t col0 = 0, row0 = 0;
  int64_t cells = 0;
};

// The largest mosaic side in samples a region step may allocate (16384^2 floats: 1 GiB a channel).
inline constexpr int64_t kMaxMosaicSide = 16384;

struct StepPlan {
  const PipelineStep* step = nullptr;
  // The step's params as the operator sees them: step->params, with the artifacts they refer to
  // ({"$artifact": NAME}) pasted in by the runner just before the step runs.
  json params;
  int level = 0;  // level of the cells (and tiles) the step reads and writes
  int tile_size = 0;
  std::vector<std::pair<std::string, LayerInfo>> inputs;  // port -> layer, in the spec's order
  std::map<std::string, LayerInfo> outputs;               // port -> raster layer (cell, region)
  std::string artifact;                                   // reduce: the artifact written
  // A step with inputs processes the first input's tiles within the region; one without, the
  // region's cells at the pipeline level; a task its raster layer's tiles, or the region's cells
  // (its run records).
  CellPlan cells;
  MosaicBox mosaic;  // region steps
};

struct RunPlan {
  std::vector<StepPlan> steps;
};

// What a task step sees of the pipeline (the runner adds threads, resume and quiet).
TaskContext task_context(const Pipeline& pipeline, const PipelineStep& step);

// Throws maquette::Error naming the step and field: an input layer neither in `store` (null: the
// store does not exist yet) nor written by an earlier step, inputs of one step at different
// levels or tile sizes, a region operator over cells of several faces or with a mosaic side above
// kMaxMosaicSide.
RunPlan plan_run(const Pipeline& pipeline, const Store* store, int threads);

// The dry-run report: steps, cell counts and the layers to be written.
void print_plan(const Pipeline& pipeline, const RunPlan& plan, std::ostream& out);

}  // namespace maquette
