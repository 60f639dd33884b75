// maquette demo: the main job on data the project can always get. With the Olinda data
// (scripts/setup.sh puts it in build/demo-data): ingest a DEM and a Landsat 7 scene, fill voids,
// derive terrain, fit a procedural texture model to the scene and synthesize the texture two
// levels finer than the DEM, then quicklooks and textured 3D Tiles. Without it: a synthetic
// terrain and its derivatives. Both are pipelines (examples/demo-*.json, built in), written to
// the output directory as demo.json with the data files' paths filled in.
#include <spdlog/spdlog.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/builtin_steps.h"
#include "cli/commands.h"
#include "core/error.h"
#include "core/output_file.h"
#include "demo_pipelines.h"
#include "runtime/runner.h"

namespace maquette::cli {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

constexpr const char* kDemDataFile = "olinda_dem_utm25s.tif";
constexpr const char* kImageryDataFile = "L7_ETMs.tif";

struct DemoOptions {
  std::string output = "demo-output";
  std::string data;  // default: demo-data next to the program's bin/
  int threads = 0;
};

// build/bin/maquette -> build/demo-data, where scripts/setup.sh extracts the data.
std::string default_data_dir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? "demo-data" : (exe.parent_path().parent_path() / "demo-data").string();
}

bool has_real_data(const std::string& dir) {
  return fs::exists(fs::path(dir) / kDemDataFile) && fs::exists(fs::path(dir) / kImageryDataFile);
}

// The built-in pipeline with its ingest steps' sources in the data directory (absolute, so that
// demo.json runs from any working directory).
json demo_pipeline(bool real, const std::string& data) {
  json doc = json::parse(real ? kDemoOlinda : kDemoSynthetic);
  for (json& step : doc.at("steps"))
    if (step.at("op") == "ingest")
      for (json& source : step.at("params").at("sources"))
        source = fs::absolute(fs::path(data) / source.get<std::string>()).string();
  return doc;
}

void remove_store(const std::string& path) {
  std::error_code ec;
  for (const char* suffix : {"", "-wal", "-shm"}) fs::remove(path + suffix, ec);
}

void run_demo(const DemoOptions& o) {
  std::error_code ec;
  fs::create_directories(o.output, ec);
  if (ec) throw Error("cannot create the demo output directory " + o.output + ": " + ec.message());
  const std::string data = o.data.empty() ? default_data_dir() : o.data;
  const bool real = has_real_data(data);
  if (!real)
    spdlog::warn(
        "demo data not found in {} ({} and {} from Debian's r-cran-stars: scripts/setup.sh "
        "fetches them); running the synthetic terrain demo instead",
        data, kDemDataFile, kImageryDataFile);

  const std::string pipeline_file = (fs::path(o.output) / "demo.json").string();
  write_file_whole(pipeline_file, demo_pipeline(real, data).dump(2) + "\n");
  const Pipeline pipeline = load_pipeline(pipeline_file, program_registry());
  remove_store(pipeline.store_path);  // a demo always starts afresh
  std::string written;                // the exports, which replace earlier ones
  for (const PipelineStep& step : pipeline.steps)
    if (step.op_name == "export") {
      const std::string out = resolve_path(pipeline.base_dir, step.params.at("out"));
      if (step.params.at("format") == "tiles3d") fs::remove_all(out, ec);
      written += "\n  " + out;
    }
  if (real)
    spdlog::info("demo: the Olinda DEM and Landsat 7 scene from {}", data);
  else
    spdlog::info("demo: synthetic terrain, {} cells at level {} ({} px tiles)",
                 pipeline.region.size(), pipeline.level, pipeline.tile_size);
  RunOptions run;
  run.threads = o.threads;
  run.quiet = global_options().quiet;
  const RunSummary summary = run_pipeline(pipeline, run);
  const std::string tiles_dir = (fs::path(o.output) / "tiles3d").string();
  std::printf(
      "Demo (%s) finished in %.1f s.\n"
      "Store:      %s\nPipeline:   %s\nWritten:%s\n"
      "Next:\n  maquette view %s      (then open the URL it prints)\n"
      "  maquette info %s\n  maquette export gtiff %s --layer dem dem.tif\n"
      "  maquette run %s --dry-run\n",
      real ? "Olinda, Brazil: Landsat 7, DEM and synthesized texture" : "synthetic terrain",
      summary.seconds, pipeline.store_path.c_str(), pipeline_file.c_str(), written.c_str(),
      tiles_dir.c_str(), pipeline.store_path.c_str(), pipeline.store_path.c_str(),
      pipeline_file.c_str());
}

}  // namespace

void add_demo_command(CLI::App& app) {
  auto o = std::make_shared<DemoOptions>();
  CLI::App* demo = app.add_subcommand(
      "demo",
      "Run the demo: ingest a DEM and a Landsat 7 scene (Olinda, Brazil; fetched by "
      "scripts/setup.sh from Debian's r-cran-stars), fill voids, derive terrain, fit a procedural "
      "texture to the scene and synthesize it 4x finer than the DEM, write PNG quicklooks and "
      "textured 3D Tiles (examples/demo-olinda.json, built in). Without that data: a synthetic "
      "terrain (examples/demo-synthetic.json)");
  demo->add_option("-o,--output", o->output, "Output directory")->capture_default_str();
  demo->add_option("--data", o->data,
                   "Directory holding olinda_dem_utm25s.tif and L7_ETMs.tif (default: "
                   "demo-data next to the program's bin/)");
  add_threads_option(demo, o->threads);
  demo->callback([o] { run_demo(*o); });
}

}  // namespace maquette::cli
