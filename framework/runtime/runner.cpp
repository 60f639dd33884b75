#include "runtime/runner.h"

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <filesystem>

#include "runtime/run_plan.h"
#include "runtime/step_exec.h"

namespace maquette {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The pipeline's store, or null when it does not exist yet.
std::unique_ptr<Store> open_existing(const Pipeline& pipeline, Store::Mode mode) {
  if (!std::filesystem::exists(pipeline.store_path)) return nullptr;
  return Store::open(pipeline.store_path, mode);
}

RunSummary dry_run(const Pipeline& pipeline, const RunOptions& options, std::ostream& out) {
  const auto store = open_existing(pipeline, Store::Mode::ReadOnly);
  const RunPlan plan = plan_run(pipeline, store.get(), std::max(options.threads, 1));
  print_plan(pipeline, plan, out);
  RunSummary summary;
  for (const auto& sp : plan.steps)
    summary.steps.push_back({sp.step->label(), int64_t(sp.cells.size()), 0, 0, 0.0});
  return summary;
}

// FNV-1a of the sorted cell ids: a region file giving other cells gives another run identity.
std::string cells_hash(const std::vector<CellId>& cells) {
  uint64_t h = 14695981039346656037ull;
  for (const CellId c : cells)
    for (int shift = 0; shift < 64; shift += 8)
      h = (h ^ ((c.id() >> shift) & 0xff)) * 1099511628211ull;
  return fmt::format("{:016x}", h);
}

// What identifies a run for --resume: the pipeline as written, the cells its region resolved to
// and the module (name and version) of each step's operator.
nlohmann::json run_identity(const Pipeline& pipeline) {
  nlohmann::json modules = nlohmann::json::array();
  for (const auto& step : pipeline.steps) modules.push_back(step.module);
  return {
      {"pipeline", pipeline.document},
      {"region_cells", {{"count", pipeline.region.size()}, {"fnv1a", cells_hash(pipeline.region)}}},
      {"modules", modules}};
}

class Runner {
 public:
  Runner(const Pipeline& pipeline, const RunOptions& options)
      : pipeline_(pipeline),
        options_(options),
        threads_(options.threads > 0 ? options.threads : tbb::info::default_concurrency()),
        parallelism_(tbb::global_control::max_allowed_parallelism, size_t(threads_)),
        arena_(threads_) {}

  RunSummary run() {
    const auto start = Clock::now();
    // Everything is validated before the store is created or written.
    store_ = open_existing(pipeline_, Store::Mode::ReadWrite);
    const RunPlan plan = plan_run(pipeline_, store_.get(), threads_);
    if (!store_) store_ = Store::open(pipeline_.store_path, Store::Mode::Create);
    // Creating every output layer first also checks them against existing layers before any
    // cell is computed.
    for (const auto& sp : plan.steps)
      for (const auto& [port, layer] : sp.outputs) store_->create_layer(layer);

    RunSummary summary;
    const nlohmann::json identity = run_identity(pipeline_);
    if (options_.resume) {
      if (const auto id = store_->latest_unfinished_run(identity)) {
        summary.run_id = *id;
        summary.resumed = true;
        if (!options_.quiet) spdlog::info("resuming run {} of {}", *id, pipeline_.source);
      } else if (!options_.quiet) {
        spdlog::info(
            "no unfinished run of {} with the same pipeline, region cells ({}, hash {}) and "
            "modules ({}) to resume: starting a new run",
            pipeline_.source, pipeline_.region.size(),
            identity.at("region_cells").at("fnv1a").get<std::string>(),
            identity.at("modules").dump());
      }
    }
    if (!summary.resumed) summary.run_id = store_->begin_run(identity);
    try {
      for (const auto& sp : plan.steps) summary.steps.push_back(run_step(sp, summary));
    } catch (const std::exception& e) {
      store_->finish_run(summary.run_id, std::string("failed: ") + e.what());
      throw;
    } catch (...) {
      store_->finish_run(summary.run_id, "failed: unknown exception");
      throw;
    }
    store_->finish_run(summary.run_id, "ok");
    summary.seconds = seconds_since(start);
    return summary;
  }

 private:
  StepSummary run_step(const StepPlan& sp, const RunSummary& run) {
    const auto start = Clock::now();
    StepSummary s{sp.step->label(), int64_t(sp.cells.size()), 0, 0, 0.0};
    std::vector<CellId> done;
    if (run.resumed) {
      done = store_->done_cells(run.run_id, sp.step->index);
      std::sort(done.begin(), done.end());
    }
    StepIO io(*store_, sp, run.run_id);
    const OperatorKind kind = sp.step->op->spec().kind;
    if (kind == OperatorKind::Cell) {
      std::vector<CellId> todo;
      std::set_difference(sp.cells.cells().begin(), sp.cells.cells().end(), done.begin(),
                          done.end(), std::back_inserter(todo));
      s.computed = int64_t(todo.size());
      const size_t chunk = default_chunk_size(todo.size(), threads_);
      Progress progress(s.label, s.computed, options_.quiet);
      run_cell_step(sp, CellPlan(std::move(todo), chunk), io, progress, arena_);
    } else if (done.empty()) {
      // Reduce and region steps record all their cells at once, when complete.
      s.computed = s.cells;
      Progress progress(s.label, s.computed, options_.quiet);
      if (kind == OperatorKind::Reduce)
        run_reduce_step(sp, io, progress, arena_);
      else
        run_region_step(sp, io, progress);
    }
    s.skipped = s.cells - s.computed;
    // In the arena, so that the overviews' parallel loops use `threads` threads too.
    arena_.execute([&] {
      for (const auto& [port, layer] : sp.outputs) store_->update_overviews(layer.name);
    });
    s.seconds = seconds_since(start);
    return s;
  }

  const Pipeline& pipeline_;
  const RunOptions& options_;
  int threads_;
  // Without it TBB keeps at most default_concurrency() - 1 workers for the whole process, so
  // an arena of more threads than cores would get fewer. It applies to the whole process while
  // the run lasts.
  tbb::global_control parallelism_;
  tbb::task_arena arena_;
  std::unique_ptr<Store> store_;
};

}  // namespace

RunSummary run_pipeline(const Pipeline& pipeline, const RunOptions& options,
                        std::ostream& plan_out) {
  if (options.dry_run) return dry_run(pipeline, options, plan_out);
  return Runner(pipeline, options).run();
}

}  // namespace maquette
