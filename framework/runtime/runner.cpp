#include "runtime/runner.h"

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "content/content_overviews.h"
#include "core/error.h"
#include "runtime/artifact_refs.h"
#include "runtime/params_schema.h"
#include "runtime/ranks.h"
#include "runtime/run_plan.h"
#include "runtime/step_exec.h"
#include "runtime/write_relay.h"

namespace maquette {
namespace {

using Clock = std::chrono::steady_clock;

// Under --store-copies, the writer's weight (the other ranks' is 1) in sharing the cells of a
// step whose batches it alone commits (no later step reads them on the copies): it also commits
// the other ranks' batches and builds the coarser overview levels of every output layer while
// they wait (the computing ranks' batches bring the finest). 0.85 made the 2 ranks' CPU times
// equal within 2 % on benchmarks/mpi (benchmarks/README.md); the bits do not depend on it.
constexpr double kWriterWeight = 0.85;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Whether no step writes to the store (every operator is one without outputs: exports).
bool reads_only(const Pipeline& pipeline) {
  return std::all_of(pipeline.steps.begin(), pipeline.steps.end(),
                     [](const PipelineStep& s) { return s.op->spec().outputs.empty(); });
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

// What the ranks' stores must agree on under --store-copies, as each rank finds the store at
// `path` before anything writes it: every layer's tiles, features and bytes, every artifact's
// size and, with `resume`, the run to resume and its done cells by step. No store: the summary
// of an empty one.
nlohmann::json store_summary(const Pipeline& pipeline, bool resume) {
  nlohmann::json layers = nlohmann::json::object(), artifacts = nlohmann::json::object(),
                 resumed = nullptr;
  if (const auto store = open_existing(pipeline, Store::Mode::ReadOnly)) {
    for (const LayerInfo& layer : store->layers()) {
      const LayerStats stats = store->stats(layer.name);
      layers[layer.name] = {
          {"tiles", stats.tile_count}, {"features", stats.feature_count}, {"bytes", stats.bytes}};
    }
    for (const std::string& name : store->artifact_names())
      artifacts[name] = {{"bytes", store->get_artifact(name)->data.size()}};
    if (const auto run =
            resume ? store->latest_unfinished_run(run_identity(pipeline)) : std::nullopt) {
      nlohmann::json cells = nlohmann::json::array();
      for (const PipelineStep& step : pipeline.steps) {
        std::vector<CellId> done = store->done_cells(*run, step.index);
        std::sort(done.begin(), done.end());
        cells.push_back({{"count", done.size()}, {"fnv1a", cells_hash(done)}});
      }
      resumed = {{"run", *run}, {"done", cells}};
    }
  }
  return {{"layers", layers}, {"artifacts", artifacts}, {"resumed", resumed}};
}

// Throws, naming the first difference, unless every rank's store_summary is the writer's.
void check_copies(const std::vector<std::string>& summaries, const std::string& store_path) {
  const nlohmann::json writer = nlohmann::json::parse(summaries.front());
  for (size_t r = 1; r < summaries.size(); ++r) {
    const nlohmann::json copy = nlohmann::json::parse(summaries[r]);
    const nlohmann::json patch = nlohmann::json::diff(writer, copy);
    if (patch.empty()) continue;
    const nlohmann::json::json_pointer at(patch.front().at("path").get<std::string>());
    const auto value = [&](const nlohmann::json& j) {
      return j.contains(at) ? j.at(at).dump() : std::string("nothing");
    };
    throw Error(fmt::format(
        "rank {} of {}: its copy of the store {} differs from the writer's (rank 0): {} is {} "
        "there, {} in the writer's; copy the writer's store to every rank before the run "
        "(--store-copies)",
        r, summaries.size(), store_path, at.to_string(), value(copy), value(writer)));
  }
}

// Refuses a step that writes on the writer alone, outside the relayed batches: a task (ingest).
void check_relayed(const RunPlan& plan) {
  for (const auto& sp : plan.steps)
    if (sp.step->op->spec().kind == OperatorKind::Task && !sp.step->op->spec().outputs.empty())
      throw Error(sp.step->label() +
                  ": writes on the writer rank alone, which --store-copies cannot pass to the "
                  "other ranks' copies of the store: run it in a run of its own, then copy the "
                  "store to the ranks");
}

class Runner {
 public:
  Runner(const Pipeline& pipeline, const RunOptions& options, Ranks& ranks)
      : pipeline_(pipeline),
        options_(options),
        ranks_(ranks),
        quiet_(options.quiet || !ranks.root()),
        copies_(options.store_copies && ranks.size() > 1),
        threads_(options.threads > 0 ? options.threads : tbb::info::default_concurrency()),
        parallelism_(tbb::global_control::max_allowed_parallelism, size_t(threads_)),
        arena_(threads_) {}

  // Resuming `run` finishes the steps it left unfinished: an output layer of such a step must
  // still hold its mark. A later run that wrote the layer (another pipeline, or this one without
  // --resume) left it whole or marked by itself: resumed, it would be half the later run's tiles
  // and half the resumed one's, marked complete.
  void check_resumable(const RunPlan& plan, int64_t run) const {
    for (const StepPlan& sp : plan.steps) {
      if (sp.outputs.empty() || store_->done_cells(run, sp.step->index).size() >= sp.cells.size())
        continue;
      for (const auto& [port, layer] : sp.outputs) {
        const std::optional<int64_t> marked = store_->incomplete_run(layer.name);
        if (marked == run) continue;
        throw Error(sp.step->label() + ": outputs." + port + ": layer '" + layer.name +
                    "' was written after run " + std::to_string(run) + " stopped" +
                    (marked ? " (by run " + std::to_string(*marked) + ", unfinished)" : "") +
                    ": resuming would mix the two runs' tiles; run the pipeline without "
                    "--resume");
      }
    }
  }

  RunSummary run() {
    const auto start = Clock::now();
    RunSummary summary;
    RunPlan plan;
    // Under --store-copies the copies are checked against the writer's store before any rank
    // writes: a refused run leaves every store as it was.
    if (copies_)
      check_copies(
          exchange(ranks_, [&] { return store_summary(pipeline_, options_.resume).dump(); }),
          pipeline_.store_path);
    // The root validates everything, creates the store, its layers and the run record; then the
    // other ranks open the store and make the same plan.
    const std::string run =
        exchange(ranks_, [&] { return ranks_.root() ? prepare(plan, summary) : ""; }).front();
    std::vector<std::vector<CellId>> done;  // by step
    try {
      // Every rank reads the done cells before any rank writes, so all share the same cells.
      exchange(ranks_, [&] {
        if (!ranks_.root()) join(run, plan, summary);
        done.resize(plan.steps.size());
        for (size_t i = 0; i < plan.steps.size() && summary.resumed; ++i) {
          done[i] = store_->done_cells(summary.run_id, plan.steps[i].step->index);
          std::sort(done[i].begin(), done[i].end());
        }
        return "";
      });
      if (copies_) relay_.emplace(ranks_, *store_);
      // Cell and reduce steps run on every rank; with copies the others on the writer alone, and
      // a copy holds only what a later step of every rank reads.
      const auto on_every_rank = [](const StepPlan& step) {
        const OperatorKind k = step.step->op->spec().kind;
        return k == OperatorKind::Cell || k == OperatorKind::Reduce;
      };
      for (size_t i = 0; i < plan.steps.size(); ++i) {
        exchange(ranks_, [&] {  // every rank running it reads the artifacts; a failure fails all
          if (!copies_ || ranks_.root() || on_every_rank(plan.steps[i])) {
            paste_artifacts(plan.steps[i]);
            read_features(plan.steps[i]);
          }
          return "";
        });
        to_copies_ =
            copies_ && std::any_of(plan.steps.begin() + i + 1, plan.steps.end(), on_every_rank);
        started_ = i + 1;
        summary.steps.push_back(run_step(plan.steps[i], done[i], summary.run_id));
      }
    } catch (const std::exception& e) {
      fail(summary.run_id, std::string("failed: ") + e.what(), plan);
      throw;
    } catch (...) {
      fail(summary.run_id, "failed: unknown exception", plan);
      throw;
    }
    exchange(ranks_, [&] {
      if (ranks_.root() && summary.run_id != 0) store_->finish_run(summary.run_id, "ok");
      return "";
    });
    summary.seconds = seconds_since(start);
    return summary;
  }

 private:
  // On the root: the store, its output layers and the run record. Returns the run for join().
  std::string prepare(RunPlan& plan, RunSummary& summary) {
    // A pipeline that only reads (exports) runs on a store it cannot write, without run records
    // (run 0): e.g. a store on a read-only file system.
    if (reads_only(pipeline_) && std::filesystem::exists(pipeline_.store_path)) {
      try {
        Store::check_writable(pipeline_.store_path);
      } catch (const Error& e) {
        if (!quiet_) spdlog::info("{}; the pipeline only reads it: no run record", e.what());
        store_ = Store::open(pipeline_.store_path, Store::Mode::ReadOnly);
        plan = plan_run(pipeline_, store_.get(), threads_);
        return nlohmann::json{{"run", 0}, {"resumed", false}}.dump();
      }
    }
    // Everything is validated before the store is created or written.
    store_ = open_existing(pipeline_, Store::Mode::ReadWrite);
    plan = plan_run(pipeline_, store_.get(), threads_);
    if (copies_) check_relayed(plan);
    const nlohmann::json identity = run_identity(pipeline_);
    const std::optional<int64_t> resumable =
        options_.resume && store_ ? store_->latest_unfinished_run(identity) : std::nullopt;
    if (resumable) check_resumable(plan, *resumable);
    if (!store_) {
      if (const auto dir = std::filesystem::path(pipeline_.store_path).parent_path(); !dir.empty())
        std::filesystem::create_directories(dir);
      store_ = Store::open(pipeline_.store_path, Store::Mode::Create);
    }
    // Every output layer is created before any cell is computed (plan_run checked them
    // against the stored layers).
    create_outputs(plan);

    if (options_.resume) {
      if (const auto id = resumable) {
        summary.run_id = *id;
        summary.resumed = true;
        if (!quiet_) spdlog::info("resuming run {} of {}", *id, pipeline_.source);
      } else if (!quiet_) {
        spdlog::info(
            "no unfinished run of {} with the same pipeline, region cells ({}, hash {}) and "
            "modules ({}) to resume: starting a new run",
            pipeline_.source, pipeline_.region.size(),
            identity.at("region_cells").at("fnv1a").get<std::string>(),
            identity.at("modules").dump());
      }
    }
    if (!summary.resumed) summary.run_id = store_->begin_run(identity);
    // Readers refuse the output layers until their step is done (a killed run leaves them so).
    for (const auto& sp : plan.steps)
      for (const auto& [port, layer] : sp.outputs)
        store_->mark_incomplete(layer.name, summary.run_id);
    return nlohmann::json{{"run", summary.run_id}, {"resumed", summary.resumed}}.dump();
  }

  // On the other ranks, once the root has prepared the run.
  void join(const std::string& run, RunPlan& plan, RunSummary& summary) {
    const nlohmann::json j = nlohmann::json::parse(run);
    summary.run_id = j.at("run").get<int64_t>();
    summary.resumed = j.at("resumed").get<bool>();
    const bool writes = summary.run_id != 0;
    // Under --store-copies, this rank's copy: made now when absent (check_copies passed, so the
    // writer's store was new too), with the output layers the writer created.
    const bool create = copies_ && writes && !std::filesystem::exists(pipeline_.store_path);
    store_ = Store::open(pipeline_.store_path, !writes  ? Store::Mode::ReadOnly
                                               : create ? Store::Mode::Create
                                                        : Store::Mode::ReadWrite);
    plan = plan_run(pipeline_, store_.get(), threads_);
    if (copies_ && writes) create_outputs(plan);
  }

  // Creates the run's output layers in this rank's store (a step's layer is no other step's:
  // check_distinct_outputs), keeping those that were complete as they were, provenance included,
  // to be restored if the run fails before writing them (fail()).
  void create_outputs(const RunPlan& plan) {
    untouched_.clear();
    for (const auto& sp : plan.steps)
      for (const auto& [port, layer] : sp.outputs) {
        if (const auto stored = store_->layer(layer.name);
            stored && !store_->incomplete(layer.name))
          untouched_.emplace(layer.name, *stored);
        store_->create_layer(layer);
      }
  }

  // Marks the run failed (on the root) and restores its untouched layers (below) in the store,
  // and under --store-copies in every rank's copy, which took the run's provenance too; no rank
  // leaves before, since a launcher may end the job as soon as one rank exits with an error.
  void fail(int64_t run_id, const std::string& status, const RunPlan& plan) {
    const std::vector<std::string> restored = exchange(ranks_, [&] {
      if (!ranks_.root() || run_id == 0) return std::string();
      const std::vector<std::string> layers = layers_to_restore(run_id, plan);
      restore(layers);
      store_->finish_run(run_id, status);
      return nlohmann::json(layers).dump();
    });
    if (copies_ && !ranks_.root() && !restored.front().empty())
      restore(nlohmann::json::parse(restored.front()).get<std::vector<std::string>>());
  }

  // A failed run leaves readable, with the provenance they had, the layers that were complete
  // before it and that it has not written: those of the steps it never started, and of the step
  // that failed when that step recorded no cell in this run (cell, reduce and region steps record a
  // cell with its tiles, in one transaction; a task, an ingest, writes its tiles first: its layers
  // stay marked). On the root.
  std::vector<std::string> layers_to_restore(int64_t run_id, const RunPlan& plan) const {
    const auto wrote = [&](size_t i) {
      const int step = plan.steps[i].step->index;
      return i + 1 < started_ ||
             (i + 1 == started_ && (plan.steps[i].step->op->spec().kind == OperatorKind::Task ||
                                    !store_->done_cells(run_id, step).empty() ||
                                    !store_->done_keys(run_id, step).empty()));
    };
    std::set<std::string> written;
    for (size_t i = 0; i < plan.steps.size(); ++i)
      for (const auto& [port, layer] : plan.steps[i].outputs)
        if (wrote(i)) written.insert(layer.name);
    std::vector<std::string> out;
    for (const auto& [layer, stored] : untouched_)
      if (!written.count(layer)) out.push_back(layer);
    return out;
  }

  // Those of `layers` this rank's store held complete before the run, as they were.
  void restore(const std::vector<std::string>& layers) {
    for (const std::string& layer : layers)
      if (const auto stored = untouched_.find(layer); stored != untouched_.end()) {
        store_->create_layer(stored->second);  // the same definition: its provenance back
        store_->mark_complete(layer);
      }
  }

  // The artifacts the step's params refer to, now written by the earlier steps, pasted in and
  // validated against the operator's schema and checked (OperatorSpec::check_params).
  void paste_artifacts(StepPlan& sp) const {
    const PipelineStep& step = *sp.step;
    if (artifact_refs(step.params).empty()) return;
    sp.params = validate_params(step.op->spec().params_schema,
                                maquette::paste_artifacts(step.params, *store_, step.label()),
                                step.label());
    check_step_params(step, sp.params);
  }

  // The features of the ports whose layers an earlier step has written in this run.
  void read_features(StepPlan& sp) const {
    for (FeaturePort& f : sp.features)
      if (!f.index)
        f.index = std::make_shared<const FeatureIndex>(*store_, f.layer,
                                                       sp.step->label() + ": inputs." + f.port);
  }

  StepSummary run_step(const StepPlan& sp, const std::vector<CellId>& done, int64_t run_id) {
    const auto start = Clock::now();
    StepSummary s{sp.step->label(), int64_t(sp.cells.size()), 0, 0, 0.0};
    for (const auto& [port, layer] : sp.step->inputs) {
      try {
        if (store_->layer(layer)) store_->require_layer(layer);  // refuses an incomplete one
      } catch (const Error& e) {
        throw Error(sp.step->label() + ": inputs." + port + ": " + e.what());
      }
    }
    // A region over no tile of the first input (a bbox beside the data) computes nothing: said.
    if (sp.cells.size() == 0 && !sp.inputs.empty() && !quiet_)
      spdlog::warn("{}: no tile of inputs.{} (layer '{}') lies in the region: nothing computed",
                   s.label, sp.inputs.front().first, sp.inputs.front().second.name);
    StepIO io(*store_, sp, run_id, relay_ ? &*relay_ : nullptr);
    const OperatorKind kind = sp.step->op->spec().kind;
    if (kind == OperatorKind::Cell) {
      std::vector<CellId> todo;
      std::set_difference(sp.cells.cells().begin(), sp.cells.cells().end(), done.begin(),
                          done.end(), std::back_inserter(todo));
      s.computed = int64_t(todo.size());
      const CellPlan mine = share(std::move(todo));
      io.group_siblings(mine.cells());
      relayed_exchange([&] {
        Progress progress(s.label, int64_t(mine.size()), quiet_);
        try {
          run_cell_step(sp, mine, io, progress, arena_);
        } catch (...) {
          // The cells computed before the failing one are kept, as without groups; a failure to
          // keep them must not hide the error that names the step and the cell, but is said.
          try {
            io.flush();
          } catch (const std::exception& e) {
            spdlog::error("{}: the cells finished before the failure were not kept either: {}",
                          s.label, e.what());
          }
          throw;
        }
        io.flush();
      });
    } else if (done.empty()) {
      // Reduce, region and task steps record all their cells at once, when complete.
      s.computed = s.cells;
      if (kind == OperatorKind::Reduce)
        run_reduce(sp, io);
      else if (kind == OperatorKind::Task)
        relayed_exchange([&] {
          if (ranks_.root()) run_task(sp, io, run_id);
        });
      else
        relayed_exchange([&] {
          // A region operator sees the whole mosaic at once: the root runs it alone.
          if (ranks_.root()) {
            Progress progress(s.label, s.computed, quiet_);
            run_region_step(sp, io, progress);
          }
        });
    }
    s.skipped = s.cells - s.computed;
    exchange(ranks_, [&] {
      update_overviews(sp);
      return "";
    });
    exchange(ranks_, [&] {
      if (ranks_.root() || copies_)  // a copy may hold the marks of the run it was copied in
        for (const auto& [port, layer] : sp.outputs) store_->mark_complete(layer.name);
      return "";
    });
    s.seconds = seconds_since(start);
    return s;
  }

  // Each rank maps its share; the root merges all partials in cell-id order (rank order is
  // cell-id order) and writes the artifact. Partials travel as CBOR, which keeps every double,
  // NaN included; a single process takes the same path, so the bits cannot depend on the ranks.
  void run_reduce(const StepPlan& sp, StepIO& io) {
    const CellPlan mine = share(sp.cells.cells());
    const std::vector<std::string> parts = exchange(ranks_, [&] {
      Progress progress(sp.step->label(), int64_t(mine.size()), quiet_);
      const auto cbor =
          nlohmann::json::to_cbor(nlohmann::json(map_reduce_cells(sp, mine, io, progress, arena_)));
      return std::string(cbor.begin(), cbor.end());
    });
    relayed_exchange([&] {
      if (!ranks_.root()) return;
      std::vector<nlohmann::json> partials;
      for (const std::string& part : parts)
        for (nlohmann::json& p : nlohmann::json::from_cbor(part)) partials.push_back(std::move(p));
      finish_reduce_step(sp, partials, io);
    });
  }

  // A task runs on the root (an ingest writes its layer with its own threads).
  void run_task(const StepPlan& sp, StepIO& io, int64_t run_id) const {
    TaskContext ctx = task_context(pipeline_, *sp.step);
    ctx.params = &sp.params;
    ctx.threads = threads_;
    ctx.resume = options_.resume;
    ctx.quiet = quiet_;
    try {
      static_cast<const TaskOperator&>(*sp.step->op).run(ctx);
    } catch (const std::exception& e) {
      throw Error(sp.step->label() + " failed: " + e.what());
    }
    if (run_id != 0) io.write_done(sp.cells.cells());
  }

  // The step's output layers are shared out among the ranks (each layer's overviews depend on
  // its own tiles or content only); under --store-copies the writer builds them all, and so does
  // each copy when later steps may read them (terrain.fill_voids does). In the arena, so
  // that the overviews' parallel loops use `threads` threads. Content layers get simplified
  // content (content/content_overviews.h).
  void update_overviews(const StepPlan& sp) {
    int i = 0;
    arena_.execute([&] {
      for (const auto& [port, layer] : sp.outputs) {
        if (copies_ ? !ranks_.root() && !to_copies_ : i++ % ranks_.size() != ranks_.rank())
          continue;
        if (layer.kind == LayerKind::Raster)
          store_->update_overviews(layer.name);
        else
          update_content_overviews(*store_, layer.name);
      }
    });
  }

  // exchange() of `work` on every rank; under --store-copies, while the ranks' batches are
  // relayed to the writer and the copies (write_relay.h).
  void relayed_exchange(const std::function<void()>& work) {
    exchange(ranks_, [&] {
      if (relay_)
        relay_->run(work, to_copies_);
      else
        work();
      return "";
    });
  }

  // This rank's contiguous part of `cells` (sorted), in chunks for its threads.
  CellPlan share(std::vector<CellId> cells) const {
    const CellPlan part =
        CellPlan(std::move(cells), 1)
            .share(ranks_.rank(), ranks_.size(), copies_ && !to_copies_ ? kWriterWeight : 1.0);
    return CellPlan(part.cells(), default_chunk_size(part.size(), threads_));
  }

  const Pipeline& pipeline_;
  const RunOptions& options_;
  Ranks& ranks_;
  bool quiet_;   // progress and logs from the root only
  bool copies_;  // RunOptions::store_copies, with more than one rank
  // Under --store-copies, whether the current step's writes and overviews go to the copies too:
  // only when a later step (cell or reduce) runs on every rank and may read them.
  bool to_copies_ = false;
  int threads_;
  // Without it TBB keeps at most default_concurrency() - 1 workers for the whole process, so
  // an arena of more threads than cores would get fewer. It applies to the whole process while
  // the run lasts.
  tbb::global_control parallelism_;
  tbb::task_arena arena_;
  // On the root: the output layers complete before the run (restore_untouched); and how many
  // steps the run has started.
  std::map<std::string, LayerInfo> untouched_;
  size_t started_ = 0;
  std::unique_ptr<Store> store_;     // on ranks but the root under --store-copies: this rank's copy
  std::optional<WriteRelay> relay_;  // under --store-copies
};

}  // namespace

RunSummary run_pipeline(const Pipeline& pipeline, const RunOptions& options,
                        std::ostream& plan_out) {
  const std::unique_ptr<Ranks> alone = options.ranks ? nullptr : single_process();
  Ranks& ranks = options.ranks ? *options.ranks : *alone;
  try {
    if (options.dry_run) {
      std::ostringstream discard;  // the plan is printed once, by the root
      return dry_run(pipeline, options, ranks.root() ? plan_out : discard);
    }
    return Runner(pipeline, options, ranks).run();
  } catch (const Error& e) {  // "step 2 (op) failed on cell ...": of which pipeline
    throw Error(pipeline.source + ": " + e.what());
  }
}

}  // namespace maquette
