// Executing one step of each operator kind (used by the runner).
#pragma once

#include <tbb/task_arena.h>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "runtime/cell_plan.h"
#include "runtime/progress.h"
#include "runtime/run_plan.h"
#include "runtime/step_io.h"

namespace maquette {

// Calls fn(index in `cells`, cell) for every cell, chunk by chunk on the arena's threads. After a
// failure no cell after the failing one starts, but those before it still run: the failure
// thrown, as maquette::Error "LABEL failed on cell N1234: what" (any exception, even one not
// derived from std::exception), is that of the lowest failing cell, whatever the thread count.
void for_each_cell(const CellPlan& cells, tbb::task_arena& arena, const std::string& label,
                   const std::function<void(size_t, CellId)>& fn);

// Cell operator: `todo` (the step's cells not yet done), each written with its run record.
void run_cell_step(const StepPlan& plan, const CellPlan& todo, StepIO& io, Progress& progress,
                   tbb::task_arena& arena);
// Reduce operator, in two parts so that each rank can map its share: the partials of `cells`
// (mapped in parallel, in the order of `cells`), then the merge of all the step's partials in
// cell-id order, finished into the artifact, written with the run records of all its cells.
std::vector<json> map_reduce_cells(const StepPlan& plan, const CellPlan& cells, StepIO& io,
                                   Progress& progress, tbb::task_arena& arena);
void finish_reduce_step(const StepPlan& plan, const std::vector<json>& partials, StepIO& io);
// Region operator: one mosaic of the step's cells (on one face), split back into cells.
void run_region_step(const StepPlan& plan, StepIO& io, Progress& progress);

}  // namespace maquette
