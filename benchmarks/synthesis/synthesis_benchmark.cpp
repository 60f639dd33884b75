// synthesis.transfer's speed (modules/synthesis) on the fixture of zion_fixture.h, CPU time of
// all threads (MeasureProcessCPUTime; the Time column is the wall):
//  - Analyse/threads: the exemplar's analysis (pyramid, PCA, k-coherence candidates), once per
//    process in a run, timed apart, on 1 and 2 threads (1-thread CPU against 2-thread wall: its
//    serial part).
//  - Usage/threads: the exemplar's over-use measure (exemplar_usage.h: a synthesis of its own
//    label map, in tiles), the rest of the analysis, timed apart, on 1 and 2 threads.
//  - Transfer/threads: a 512 x 512 output as 4 tiles of 256 (the operator's cells at level 10),
//    each from its own guides and halo, on 1 and 2 threads; items are output pixels, so
//    s per output megapixel = 1e6 / items_per_second.
//  - WholeImage: the same 512 x 512 output synthesized as one window: the tiling overhead is
//    Transfer's time over this one.
#include <benchmark/benchmark.h>
#include <tbb/task_arena.h>

#include "exemplar_usage.h"
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
  Exemplar e{finest.width,    finest.height,   finest.rgb,     finest.labels,
             finest.altitude, finest.excluded, finest.distance};
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

void BM_Transfer(benchmark::State& state) {
  const auto t = zion_exemplar();
  for (auto _ : state)
    benchmark::DoNotOptimize(synthesize_tiles(*t, kOut, kTile, int(state.range(0))));
  state.SetItemsProcessed(state.iterations() * kOut.width * kOut.height);
}
BENCHMARK(BM_Transfer)->Apply(on_1_and_2_threads);

void BM_WholeImage(benchmark::State& state) {
  const auto t = zion_exemplar();
  for (auto _ : state) benchmark::DoNotOptimize(synthesize_tiles(*t, kOut, int(kOut.width), 1));
  state.SetItemsProcessed(state.iterations() * kOut.width * kOut.height);
}
BENCHMARK(BM_WholeImage)->MeasureProcessCPUTime()->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
}  // namespace maquette::synthesis::bench

BENCHMARK_MAIN();
