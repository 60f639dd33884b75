// CPU of the ingest's tile pass alone, one thread: `TileResampler::make` (sample positions, the
// source window read, the kernel) over every cell of a real source's ingest, as planned by
// `maquette ingest` with its default level (or the one given) and tile size. Inputs from
// ../shared/data (the benchmark is skipped when absent); samples/s counts the tile samples made.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <optional>
#include <string>

#include "core/grid.h"
#include "gdal/raster_ingest.h"
#include "gdal/tile_resampler.h"

namespace maquette {
namespace {

void tile_pass(benchmark::State& state, const std::string& rel, const std::string& as,
               Resampling resampling, std::optional<int> level = std::nullopt) {
  const std::string path = std::string(MAQUETTE_SHARED_DIR) + "/data/" + rel;
  if (!std::filesystem::exists(path)) {
    state.SkipWithError(("../shared/data/" + rel + " is absent").c_str());
    return;
  }
  RasterIngestOptions o;
  o.layer = "l";
  o.as = as;
  o.resampling = resampling;
  o.level = level;
  const RasterIngestPlan plan = plan_raster_ingest("unused.mqt", {path}, o);
  const int size = plan.layer.tile_size;
  Tile<float> tile;
  int64_t samples = 0;
  for (auto _ : state) {
    // A new resampler each time, as each ingest thread has: its GDAL handle starts cold.
    TileResampler resampler(default_grid(), plan.sources, plan.resampling,
                            plan.layer.semantics == Semantics::Categorical);
    for (CellId cell : plan.cells) benchmark::DoNotOptimize(resampler.make(cell, size, tile));
    samples += int64_t(plan.cells.size()) * size * size;
  }
  state.counters["samples/s"] = benchmark::Counter(double(samples), benchmark::Counter::kIsRate);
}

BENCHMARK_CAPTURE(tile_pass, rainier_bilinear, "srtm3/mt_rainier_90m.tif", "dem",
                  Resampling::Bilinear)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(tile_pass, landsat_bilinear, "zion/landsat_b4.tif", "imagery",
                  Resampling::Bilinear)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(tile_pass, landsat_bilinear_level12, "zion/landsat_b4.tif", "imagery",
                  Resampling::Bilinear, 12)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(tile_pass, landsat_cubic, "zion/landsat_b4.tif", "imagery", Resampling::Cubic)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(tile_pass, nlcd_nearest, "zion/nlcd.tif", "landcover", Resampling::Nearest)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace maquette

BENCHMARK_MAIN();
