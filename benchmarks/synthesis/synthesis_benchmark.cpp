// synthesis.transfer's speed (modules/synthesis) on the fixture of zion_fixture.h, CPU time of
// all threads (MeasureProcessCPUTime; the Time column is the wall):
//  - Analyse/threads: the exemplar's analysis (pyramid, PCA, k-coherence candidates), once per
//    process in a run, timed apart, on 1 and 2 threads (1-thread CPU against 2-thread wall: its
//    serial part).
//  - Usage/threads: the exemplar's over-use measure (exemplar_usage.h: a synthesis of its own
//    label map, in tiles), the rest of the analysis, timed apart, on 1 and 2 threads.
//  - AnalyseCached: the whole analysed exemplar (transfer_exemplar's: the analysis and the usage)
//    read back from the persistent cache (exemplar_cache.h): its key made (the painting's bytes
//    hashed), the file read and decoded, what a run with a warm cache pays instead; CacheStore: the
//    file encoded and written, what a cold run adds to the analysis.
//  - Transfer/threads: a 512 x 512 output as 4 tiles of 256 (the operator's cells at level 10),
//    each from its own guides and halo, on 1 and 2 threads; items are output pixels, so
//    s per output megapixel = 1e6 / items_per_second.
//  - WholeImage: the same 512 x 512 output synthesized as one window: the tiling overhead is
//    Transfer's time over this one.
//  - TransferExampleWeights/threads, WholeImageExampleWeights: the same two with the weights of
//    examples/synthesis-zion.json (read from it: the vote of radius 2 and its balance, the patch
//    passes, the over-use and spread weights...) in place of the defaults.
//  - TransferWanted/wanted: one tile of 256 of which only the left `wanted` % of columns are
//    kept (synthesize()'s `wanted`, as the operator keeps the pixels with land cover), one thread:
//    items are the kept pixels.
//  - TurnedEdgeBand/band: one polar cell of 256 beside a turned edge (N's cell at level 2 next
//    to P, turned_edges.h) on the fixture's labels, on one thread: its own synthesis alone
//    (band:0, what any cell costs) and with the band synthesized in P's chart and cut in (band:1).
#include <benchmark/benchmark.h>
#include <tbb/task_arena.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "core/face_plane.h"
#include "core/grid.h"
#include "exemplar_cache.h"
#include "exemplar_usage.h"
#include "transfer_params.h"
#include "turned_edges.h"
#include "zion_fixture.h"

namespace maquette::synthesis::bench {
namespace {

constexpr PixelRect kOut{0, 0, 512, 512};
constexpr int kTile = 256;

// Once on 1 and once on 2 threads (state.range(0)), CPU of every thread, in seconds.
void on_1_and_2_threads(benchmark::internal::Benchmark* b) {
  b->ArgName("threads")
      ->Arg(1)
      ->Arg(2)
      ->MeasureProcessCPUTime()
      ->Unit(benchmark::kSecond)
      ->Iterations(1);
}

void BM_Analyse(benchmark::State& state) {
  const ExemplarLevel& finest = zion_exemplar()->pyramid.levels[0];
  Exemplar e{finest.width,    finest.height,   finest.rgb,      finest.labels,
             finest.altitude, finest.excluded, finest.distance, finest.light};
  for (float& v : e.rgb) v *= 255.0f;  // analyse_exemplar's input range
  for (auto _ : state)
    tbb::task_arena(int(state.range(0))).execute([&] {
      benchmark::DoNotOptimize(analyse_exemplar(e, kLevels, zion_params().at("k")));
    });
}
BENCHMARK(BM_Analyse)->Apply(on_1_and_2_threads);

void BM_Usage(benchmark::State& state) {
  ExemplarPyramid pyramid = zion_exemplar()->pyramid;
  for (auto _ : state)
    tbb::task_arena(int(state.range(0))).execute([&] {
      measure_usage(pyramid, SynthesisParams{});
    });
}
BENCHMARK(BM_Usage)->Apply(on_1_and_2_threads);

// A cache directory of this process's own, removed when the benchmark ends.
struct TemporaryCache {
  std::filesystem::path dir = std::filesystem::temp_directory_path() /
                              ("maquette-benchmark-cache-" + std::to_string(getpid()));
  std::string key = "benchmark";
  TemporaryCache() { std::filesystem::create_directories(dir); }
  ~TemporaryCache() { std::filesystem::remove_all(dir); }
};

void BM_CacheStore(benchmark::State& state) {
  const auto t = zion_exemplar();
  const TemporaryCache cache;
  for (auto _ : state)
    cached_exemplar(cache.dir, cache.key, [&] { return t; });  // nothing there yet: stored
  state.SetBytesProcessed(
      int64_t(std::filesystem::file_size(exemplar_cache_file(cache.dir, cache.key))));
}
BENCHMARK(BM_CacheStore)->MeasureProcessCPUTime()->Unit(benchmark::kSecond)->Iterations(1);

void BM_AnalyseCached(benchmark::State& state) {
  const auto t = zion_exemplar();
  const TemporaryCache cache;
  cached_exemplar(cache.dir, cache.key, [&] { return t; });
  for (auto _ : state) {
    // The key as a run makes it: the painting's bytes hashed.
    benchmark::DoNotOptimize(exemplar_cache_key(exemplar_key_params(zion_params()),
                                                exemplar_input_files(zion_params())));
    benchmark::DoNotOptimize(cached_exemplar(cache.dir, cache.key, [&] {
      state.SkipWithError("the cache missed");
      return t;
    }));
  }
}
BENCHMARK(BM_AnalyseCached)->MeasureProcessCPUTime()->Unit(benchmark::kSecond)->Iterations(3);

// kOut in tiles of `tile` on `threads` threads with `params`; items are output pixels.
void transfer(benchmark::State& state, int tile, int threads, const SynthesisParams& params) {
  const auto t = zion_exemplar();
  for (auto _ : state) benchmark::DoNotOptimize(synthesize_tiles(*t, kOut, tile, threads, params));
  state.SetItemsProcessed(state.iterations() * kOut.width * kOut.height);
}

// The weights and choices of examples/synthesis-zion.json's synthesis.transfer, on the fixture's
// class table.
SynthesisParams example_weights() {
  return synthesis_params(
      zion_weights(bench::example_weights("synthesis-zion.json"), "synthesis_benchmark"));
}

void BM_Transfer(benchmark::State& state) { transfer(state, kTile, int(state.range(0)), {}); }
BENCHMARK(BM_Transfer)->Apply(on_1_and_2_threads);

void BM_WholeImage(benchmark::State& state) { transfer(state, int(kOut.width), 1, {}); }
BENCHMARK(BM_WholeImage)->MeasureProcessCPUTime()->Unit(benchmark::kSecond)->Iterations(1);

void BM_TransferExampleWeights(benchmark::State& state) {
  transfer(state, kTile, int(state.range(0)), example_weights());
}
BENCHMARK(BM_TransferExampleWeights)->Apply(on_1_and_2_threads);

void BM_WholeImageExampleWeights(benchmark::State& state) {
  transfer(state, int(kOut.width), 1, example_weights());
}
BENCHMARK(BM_WholeImageExampleWeights)
    ->MeasureProcessCPUTime()
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

// One tile of 256 whose left `wanted` % of columns are kept (synthesize()'s `wanted`: the land,
// where the rest has no land cover), one thread: the cost follows the kept share.
void BM_TransferWanted(benchmark::State& state) {
  const auto t = zion_exemplar();
  const PixelRect out{0, 0, kTile, kTile};
  const int halo = synthesis_halo();
  TargetGuides g;
  g.rect = {-halo, -halo, kTile + 2 * halo, kTile + 2 * halo};
  g.labels = zion_labels(g.rect);
  std::vector<uint8_t> wanted(size_t(kTile) * kTile);
  for (size_t i = 0; i < wanted.size(); ++i)
    wanted[i] = int64_t(i % kTile) * 100 < state.range(0) * kTile;
  for (auto _ : state)
    benchmark::DoNotOptimize(synthesize(t->pyramid, g, SynthesisParams{}, out, wanted));
  state.SetItemsProcessed(state.iterations() * kTile * kTile * state.range(0) / 100);
}
BENCHMARK(BM_TransferWanted)
    ->ArgName("wanted")
    ->Arg(100)
    ->Arg(50)
    ->Arg(10)
    ->MeasureProcessCPUTime()
    ->Unit(benchmark::kSecond)
    ->Iterations(3);

void BM_TurnedEdgeBand(benchmark::State& state) {
  const auto t = zion_exemplar();
  const Grid& grid = default_grid();
  const FacePlane plane(grid);
  const CellId cell = CellId::FromFaceColRow(0, 2, 3, 1);  // N's right column, off the corners
  const int halo = synthesis_halo();
  TargetGuides g;
  const auto corner = plane.tile_pixel(cell, kTile, -halo, -halo);
  g.rect = {corner[0], corner[1], kTile + 2 * halo, kTile + 2 * halo};
  g.labels = zion_labels({0, 0, g.rect.width, g.rect.height});
  g.col_period = plane.wrap_columns(cell, kTile);
  const auto first = plane.tile_pixel(cell, kTile, 0, 0);
  const auto edges =
      state.range(0) ? turned_edges(grid, plane, cell, kTile, 0) : std::vector<TurnedEdge>{};
  if (state.range(0) && edges.size() != 1) state.SkipWithError("no turned edge beside the cell");
  for (auto _ : state)
    benchmark::DoNotOptimize(
        join_turned_edges(grid, plane, t->pyramid, {}, g, halo, edges,
                          synthesize(t->pyramid, g, {}, {first[0], first[1], kTile, kTile})));
  state.SetItemsProcessed(state.iterations() * kTile * kTile);
}
BENCHMARK(BM_TurnedEdgeBand)
    ->ArgName("band")
    ->Arg(0)
    ->Arg(1)
    ->MeasureProcessCPUTime()
    ->Unit(benchmark::kSecond)
    ->Iterations(3);

}  // namespace
}  // namespace maquette::synthesis::bench

BENCHMARK_MAIN();
