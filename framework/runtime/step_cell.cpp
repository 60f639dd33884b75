#include "core/error.h"
#include "runtime/step_exec.h"

namespace maquette {
namespace {

CellContext context(const StepPlan& plan, const StepIO& io, CellId cell) {
  return CellContext{cell,         plan.tile_size, plan.step->refine, &default_grid(),
                     &plan.params, &io.store(),    &plan.inputs};
}

}  // namespace

void run_cell_step(const StepPlan& plan, const CellPlan& todo, StepIO& io, Progress& progress,
                   tbb::task_arena& arena) {
  const auto& op = static_cast<const CellOperator&>(*plan.step->op);  // kind checked on loading
  const int halo = op.spec().halo;
  for_each_cell(todo, arena, plan.step->label(), [&](size_t, CellId cell) {
    CellData data = io.load(cell, halo);
    op.run(context(plan, io, cell), data);
    const CellOutput out{cell, &data.outputs, io.encode_content(cell, data.content)};
    io.write({&out, 1});
    progress.advance();
  });
}

std::vector<json> map_reduce_cells(const StepPlan& plan, const CellPlan& cells, StepIO& io,
                                   Progress& progress, tbb::task_arena& arena) {
  const auto& op = static_cast<const ReduceOperator&>(*plan.step->op);
  const int halo = op.spec().halo;
  std::vector<json> partials(cells.size());
  for_each_cell(cells, arena, plan.step->label(), [&](size_t i, CellId cell) {
    partials[i] = op.map(context(plan, io, cell), io.load(cell, halo));
    progress.advance();
  });
  return partials;
}

void finish_reduce_step(const StepPlan& plan, const std::vector<json>& partials, StepIO& io) {
  const auto& op = static_cast<const ReduceOperator&>(*plan.step->op);
  try {
    // Strictly in cell-id order, so the result does not depend on the thread or rank count.
    json merged;
    for (const json& p : partials)
      if (!p.is_null()) merged = merged.is_null() ? p : op.merge(merged, p);
    Artifact artifact =
        op.finish(merged, {&default_grid(), &plan.params, &io.store(), &plan.inputs});
    artifact.name = plan.artifact;
    io.write_done(plan.cells.cells(), &artifact);
  } catch (const std::exception& e) {
    throw Error(plan.step->label() + " failed: " + e.what());
  } catch (...) {
    throw Error(plan.step->label() + " failed: unknown exception");
  }
}

}  // namespace maquette
