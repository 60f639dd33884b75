// What a run will do, worked out before anything runs: for each step the layers it reads and
// writes (checked against the store and the earlier steps) and the cells it processes.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "runtime/cell_plan.h"
#include "runtime/feature_index.h"
#include "runtime/pipeline.h"
#include "runtime/task_operator.h"
#include "store/store.h"

namespace maquette {

// A region step's square mosaic: the bounding box of its cells on face `face`, `cells` cells a
// side from cell (col0, row0). For an operator that spans faces, `face` is the anchor its cells
// are unfolded around (core/unfolded_faces.h) and (col0, row0) may lie beyond its edges.
struct MosaicBox {
  int face = 0;
  int64_t col0 = 0, row0 = 0;
  int64_t cells = 0;
};

// A features port of a step and the features layer mapped to it.
struct FeaturePort {
  std::string port;
  std::string layer;
  double reach_m = 0;
  // Its features: read when planning if the layer is in the store and no earlier step writes it
  // (its features then decide the step's cells), else by the runner when the step starts.
  std::shared_ptr<const FeatureIndex> index;
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
  InputLayers inputs;                        // raster ports, in the spec's order
  std::vector<FeaturePort> features;         // features ports, in the spec's order
  std::map<std::string, LayerInfo> outputs;  // port -> raster or content layer (cell, region)
  std::string artifact;                      // reduce: the artifact written
  // A step with raster inputs processes the first one's tiles within the region; one whose
  // inputs are all features layers, the region's cells within reach of a feature (all the
  // region's cells when an earlier step writes a features layer it reads); one without inputs,
  // the region's cells at the pipeline level; a task its raster layer's tiles, or the region's
  // cells (its run records).
  CellPlan cells;
  MosaicBox mosaic;  // region steps
};

struct RunPlan {
  std::vector<StepPlan> steps;
};

// What a task step sees of the pipeline (the runner adds threads, resume and quiet).
TaskContext task_context(const Pipeline& pipeline, const PipelineStep& step);

// Throws maquette::Error naming the step and field: an input layer neither in `store` (null: the
// store does not exist yet) nor written by an earlier step, a layer of the wrong kind for its port
// (a raster layer given to a features port, or the reverse) or of other semantics or channels
// than the port takes (InputSpec::semantics, channels), raster inputs of one step at
// different levels or tile sizes, a region operator over cells of several faces (or, for one that
// spans faces, of faces that no face and its edge neighbours hold, or of three faces meeting at a
// corner) or with a mosaic side above kMaxMosaicSide, and an output naming a layer `store` holds
// with another definition (Store::check_layer).
RunPlan plan_run(const Pipeline& pipeline, const Store* store, int threads);

// The dry-run report: steps, cell counts and the layers to be written.
void print_plan(const Pipeline& pipeline, const RunPlan& plan, std::ostream& out);

}  // namespace maquette
