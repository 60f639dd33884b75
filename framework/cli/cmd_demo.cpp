// maquette demo: the main job on data the project can always get, with quicklooks.
// With the Olinda data (scripts/setup.sh puts it in build/demo-data): ingest a DEM and a Landsat 7
// scene, fill voids and derive terrain. Without it: a synthetic terrain and its derivatives.
#include <spdlog/spdlog.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "core/error.h"
#include "core/grid.h"
#include "demo_pipelines.h"
#include "gdal/raster_ingest.h"
#include "image/quicklook.h"
#include "runtime/operator_registry.h"
#include "runtime/runner.h"
#include "tiles3d/export_tiles3d.h"

namespace maquette::cli {
namespace {

namespace fs = std::filesystem;

constexpr const char* kDemDataFile = "olinda_dem_utm25s.tif";
constexpr const char* kImageryDataFile = "L7_ETMs.tif";

struct DemoOptions {
  std::string output = "demo-output";
  std::string data;  // default: demo-data next to the program's bin/
  int threads = 0;
};

struct Quicklook {
  const char* layer;
  QuicklookStyle style;
  const char* file;
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

// Ingests the Olinda DEM and the Landsat 7 scene (bands 3, 2, 1: red, green, blue).
void ingest_olinda(const std::string& store, const std::string& dir, const DemoOptions& o) {
  RasterIngestOptions dem;
  dem.layer = "dem_source";
  dem.as = "dem";
  dem.threads = o.threads;
  dem.quiet = global_options().quiet;
  ingest_raster(store, {(fs::path(dir) / kDemDataFile).string()}, dem);
  RasterIngestOptions imagery = dem;
  imagery.layer = "imagery";
  imagery.as = "imagery";
  imagery.bands = {3, 2, 1};
  ingest_raster(store, {(fs::path(dir) / kImageryDataFile).string()}, imagery);
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
  std::ofstream(pipeline_file) << (real ? kDemoOlinda : kDemoSynthetic);
  const Pipeline pipeline = load_pipeline(pipeline_file, default_registry());
  remove_store(pipeline.store_path);  // a demo always starts afresh
  if (real) {
    spdlog::info("demo: ingesting the Olinda DEM and Landsat 7 scene from {}", data);
    ingest_olinda(pipeline.store_path, data, o);
  } else {
    spdlog::info("demo: synthetic terrain, {} cells at level {} ({} px tiles)",
                 pipeline.region.size(), pipeline.level, pipeline.tile_size);
  }
  RunOptions run;
  run.threads = o.threads;
  run.quiet = global_options().quiet;
  const RunSummary summary = run_pipeline(pipeline, run);

  auto style = [](Ramp ramp, bool hillshade) {
    QuicklookStyle s;
    s.ramp = ramp;
    s.hillshade = hillshade;
    return s;
  };
  std::vector<Quicklook> looks = {{"dem", style(Ramp::Terrain, true), "dem.png"},
                                  {"hillshade", style(Ramp::Grey, false), "hillshade.png"},
                                  {"slope", style(Ramp::Slope, false), "slope.png"}};
  if (real) looks.push_back({"imagery", QuicklookStyle{}, "imagery.png"});
  const auto store = Store::open(pipeline.store_path, Store::Mode::ReadOnly);
  std::string written;
  for (const Quicklook& q : looks) {
    const std::string path = (fs::path(o.output) / q.file).string();
    write_quicklook_png(mosaic_layer(*store, default_grid(), q.layer, {}), q.style, path);
    written += "\n  " + path;
  }
  // The terrain for 3D viewers: Draco-compressed 3D Tiles, textured with the imagery if any.
  const std::string tiles_dir = (fs::path(o.output) / "tiles3d").string();
  fs::remove_all(tiles_dir, ec);
  Tiles3dExport tiles;
  tiles.terrain.dem = "dem";
  if (real) tiles.terrain.texture = "imagery";
  const int64_t tile_count = export_tiles3d(*store, default_grid(), tiles, tiles_dir);
  std::printf(
      "Demo (%s) finished in %.1f s.\n"
      "Store:      %s\nPipeline:   %s\nQuicklooks:%s\n3D Tiles:   %s (%lld tiles)\n"
      "Next:\n  maquette view %s      (then open the URL it prints)\n"
      "  maquette info %s\n  maquette export gtiff %s --layer dem dem.tif\n"
      "  maquette run %s --dry-run\n",
      real ? "Olinda, Brazil: Landsat 7 and DEM" : "synthetic terrain", summary.seconds,
      pipeline.store_path.c_str(), pipeline_file.c_str(), written.c_str(), tiles_dir.c_str(),
      static_cast<long long>(tile_count), tiles_dir.c_str(), pipeline.store_path.c_str(),
      pipeline.store_path.c_str(), pipeline_file.c_str());
}

}  // namespace

void add_demo_command(CLI::App& app) {
  auto o = std::make_shared<DemoOptions>();
  CLI::App* demo = app.add_subcommand(
      "demo",
      "Run the demo: ingest a DEM and a Landsat 7 scene (Olinda, Brazil; fetched by "
      "scripts/setup.sh from Debian's r-cran-stars), fill voids and derive terrain "
      "(examples/demo-olinda.json, built in), and write PNG quicklooks. Without that data: a "
      "synthetic terrain (examples/demo-synthetic.json)");
  demo->add_option("-o,--output", o->output, "Output directory")->capture_default_str();
  demo->add_option("--data", o->data,
                   "Directory holding olinda_dem_utm25s.tif and L7_ETMs.tif (default: "
                   "demo-data next to the program's bin/)");
  demo->add_option("-t,--threads", o->threads, "Worker threads (0: all cores)")
      ->capture_default_str();
  demo->callback([o] { run_demo(*o); });
}

}  // namespace maquette::cli
