// Running a pipeline: validate and plan everything, then run the steps in order over their cells
// on a thread pool, writing each cell with its run record so that --resume can finish a killed
// run with the same bits. See framework/runtime/README.md.
#pragma once

#include <cstdint>
#include <iostream>
#include <string>
#include <vector>

#include "runtime/pipeline.h"
#include "runtime/ranks.h"

namespace maquette {

struct RunOptions {
  int threads = 0;         // 0: all cores
  bool resume = false;     // continue the latest unfinished run of the same pipeline, region
                           // cells and module versions
  bool dry_run = false;    // validate and print the plan, write nothing
  bool quiet = false;      // no progress output
  Ranks* ranks = nullptr;  // the processes sharing the run (MPI ranks); null: this one alone
  // Ranks share no store file: rank 0, the writer, alone opens the pipeline's store; each other
  // rank reads its own copy of it at the pipeline's store path on its machine, made before the
  // run, and the ranks' writes reach the store and every copy through the writer
  // (write_relay.h). Without it every rank opens the one store file.
  bool store_copies = false;
};

struct StepSummary {
  std::string label;     // "step 1 (terrain.derive)"
  int64_t cells = 0;     // cells of the step
  int64_t computed = 0;  // cells computed by this run
  int64_t skipped = 0;   // cells already done by the resumed run
  double seconds = 0;
};

struct RunSummary {
  int64_t run_id = 0;  // run record in the store (0 for a dry run)
  bool resumed = false;
  std::vector<StepSummary> steps;
  double seconds = 0;
};

// Throws maquette::Error: validation errors before anything runs; an operator failing on a cell
// stops the run, marks it failed and throws "step 2 (terrain.derive) failed on cell N1234: ...".
// A dry run prints the plan to `plan_out`.
RunSummary run_pipeline(const Pipeline& pipeline, const RunOptions& options,
                        std::ostream& plan_out = std::cout);

}  // namespace maquette
