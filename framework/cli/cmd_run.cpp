// maquette run PIPELINE.json: validate, plan and run a pipeline.
#include <spdlog/spdlog.h>

#include <memory>
#include <string>

#include "cli/commands.h"
#include "runtime/operator_registry.h"
#include "runtime/runner.h"

namespace maquette::cli {
namespace {

struct RunCommandOptions {
  std::string pipeline;
  RunOptions run;
};

void log_summary(const RunSummary& s) {
  for (const StepSummary& step : s.steps)
    spdlog::info("{}: {} cells ({} computed, {} already done) in {:.2f} s", step.label, step.cells,
                 step.computed, step.skipped, step.seconds);
  spdlog::info("run {} {} in {:.2f} s", s.run_id, s.resumed ? "resumed and finished" : "finished",
               s.seconds);
}

}  // namespace

void add_run_command(CLI::App& app) {
  auto o = std::make_shared<RunCommandOptions>();
  CLI::App* run = app.add_subcommand(
      "run",
      "Run a pipeline (JSON: store, region, level, steps). Everything is checked before anything "
      "runs; results are identical for any thread count");
  run->add_option("PIPELINE", o->pipeline, "Pipeline JSON file")->required();
  run->add_option("-t,--threads", o->run.threads, "Worker threads (0: all cores)")
      ->capture_default_str()
      ->check(CLI::Range(0, 1024));
  run->add_flag(
      "--resume", o->run.resume,
      "Finish the latest unfinished run of the same pipeline, skipping cells it completed");
  run->add_flag("--dry-run", o->run.dry_run, "Validate and print the plan; write nothing");
  run->callback([o] {
    o->run.quiet = global_options().quiet;
    const Pipeline pipeline = load_pipeline(o->pipeline, default_registry());
    const RunSummary summary = run_pipeline(pipeline, o->run);
    if (!o->run.dry_run) log_summary(summary);
  });
}

}  // namespace maquette::cli
