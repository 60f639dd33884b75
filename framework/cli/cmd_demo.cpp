// maquette demo: the main job on data the project can always make, with quicklooks.
#include <spdlog/spdlog.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "cli/commands.h"
#include "core/error.h"
#include "core/grid.h"
#include "demo_pipeline.h"
#include "image/quicklook.h"
#include "runtime/operator_registry.h"
#include "runtime/runner.h"

namespace maquette::cli {
namespace {

struct DemoOptions {
  std::string output = "demo-output";
  int threads = 0;
};

struct Quicklook {
  const char* layer;
  Ramp ramp;
  const char* file;
};

void run_demo(const DemoOptions& o) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(o.output, ec);
  if (ec) throw Error("cannot create the demo output directory " + o.output + ": " + ec.message());
  const std::string pipeline_file = (fs::path(o.output) / "demo.json").string();
  std::ofstream(pipeline_file) << kDemoPipeline;

  const Pipeline pipeline = load_pipeline(pipeline_file, default_registry());
  // A demo always starts afresh: an earlier demo store is replaced, not resumed.
  fs::remove(pipeline.store_path, ec);
  fs::remove(pipeline.store_path + "-wal", ec);
  fs::remove(pipeline.store_path + "-shm", ec);
  spdlog::info("demo: synthetic terrain and its derivatives, {} cells at level {} ({} px tiles)",
               pipeline.region.size(), pipeline.level, pipeline.tile_size);
  RunOptions run;
  run.threads = o.threads;
  run.quiet = global_options().quiet;
  const RunSummary summary = run_pipeline(pipeline, run);

  const auto store = Store::open(pipeline.store_path, Store::Mode::ReadOnly);
  const Quicklook looks[] = {{"dem", Ramp::Terrain, "dem.png"},
                             {"hillshade", Ramp::Grey, "hillshade.png"},
                             {"slope", Ramp::Slope, "slope.png"}};
  std::string written;
  for (const Quicklook& q : looks) {
    const std::string path = (fs::path(o.output) / q.file).string();
    write_quicklook_png(mosaic_layer(*store, default_grid(), q.layer, {}), {q.ramp, std::nullopt},
                        path);
    written += "\n  " + path;
  }
  std::printf(
      "Demo finished in %.1f s.\n"
      "Store:      %s\nPipeline:   %s\nQuicklooks:%s\n"
      "Next:\n  maquette info %s\n  maquette export png %s --layer aspect aspect.png\n"
      "  maquette run %s --dry-run\n",
      summary.seconds, pipeline.store_path.c_str(), pipeline_file.c_str(), written.c_str(),
      pipeline.store_path.c_str(), pipeline.store_path.c_str(), pipeline_file.c_str());
}

}  // namespace

void add_demo_command(CLI::App& app) {
  auto o = std::make_shared<DemoOptions>();
  CLI::App* demo = app.add_subcommand(
      "demo",
      "Run the demo pipeline (examples/demo.json, built in): a synthetic terrain and its "
      "derivatives in a new store, plus PNG quicklooks");
  demo->add_option("-o,--output", o->output, "Output directory")->capture_default_str();
  demo->add_option("-t,--threads", o->threads, "Worker threads (0: all cores)")
      ->capture_default_str();
  demo->callback([o] { run_demo(*o); });
}

}  // namespace maquette::cli
