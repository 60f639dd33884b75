// maquette run PIPELINE.json: validate, plan and run a pipeline.
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <memory>
#include <string>

#include "cli/builtin_steps.h"
#include "cli/commands.h"
#include "core/error.h"
#include "runtime/operator_registry.h"
#include "runtime/ranks.h"
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

// The writer's word when the launcher ends the job under --store-copies (a rank died, or the job
// was cancelled): Open MPI's mpirun and Slurm send SIGTERM, which would end it silently. Only
// async-signal-safe calls.
extern "C" void report_ended_job(int) {
  static const char message[] =
      "maquette: error: rank 0 (the writer): the launcher is ending the job (a rank died or the "
      "job was cancelled); the store keeps every cell the writer committed: finish the run with "
      "--resume once the ranks have new copies of the store\n";
  (void)!write(STDERR_FILENO, message, sizeof message - 1);
  _exit(1);
}

}  // namespace

void add_run_command(CLI::App& app) {
  auto o = std::make_shared<RunCommandOptions>();
  CLI::App* run = app.add_subcommand(
      "run",
      "Run a pipeline (JSON: store, region, level, steps). Everything is checked before anything "
      "runs; results are identical for any thread count, and under mpirun or srun for any number "
      "of ranks");
  run->add_option("PIPELINE", o->pipeline, "Pipeline JSON file")->required();
  add_threads_option(run, o->run.threads);
  run->add_flag(
      "--resume", o->run.resume,
      "Finish the latest unfinished run of the same pipeline, skipping cells it completed");
  run->add_flag("--dry-run", o->run.dry_run, "Validate and print the plan; write nothing");
  run->add_flag("--store-copies", o->run.store_copies,
                "Under mpirun or srun, for ranks that share no file system: rank 0 alone opens "
                "the pipeline's store and writes what every rank computes; each other rank reads "
                "its own copy of the store, at the same path on its machine, copied there "
                "before the run");
  run->callback([o] {
    // Under mpirun or srun, this process is one rank of the run (MPI finalized when it ends).
    const std::unique_ptr<Ranks> ranks = launched_ranks();
    RunOptions options = o->run;
    options.ranks = ranks.get();
    options.quiet = global_options().quiet;
    const bool writer = options.store_copies && ranks->size() > 1 && ranks->root();
    if (writer) std::signal(SIGTERM, report_ended_job);
    try {
      Pipeline pipeline;
      exchange(*ranks, [&] {  // under MPI, a failure on one rank fails all
        pipeline = load_pipeline(o->pipeline, program_registry());
        return "";
      });
      const RunSummary summary = run_pipeline(pipeline, options);
      if (writer) std::signal(SIGTERM, SIG_DFL);
      if (!options.dry_run && ranks->root()) log_summary(summary);
    } catch (const Error& e) {
      if (writer) std::signal(SIGTERM, SIG_DFL);  // every rank fails alike: no job to report
      if (ranks->size() == 1) throw;
      // Every rank fails with the same message: the root prints it (as main() would) before any
      // rank exits, since a launcher ends the whole job when one rank exits with an error.
      if (ranks->root()) std::fprintf(stderr, "maquette: error: %s\n", e.what());
      ranks->all_gather("");
      throw CLI::RuntimeError(1);
    }
  });
}

}  // namespace maquette::cli
