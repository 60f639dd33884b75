// The deform benchmarks measure the CPU time of every thread (MeasureProcessCPUTime: the work,
// comparable with a single-threaded run) and report the benchmark thread's own CPU time per
// iteration as the counter main_cpu_ms: the serial parts plus the main thread's share of the
// parallel ones. On a loaded machine the main thread takes more than its half of the parallel
// work, so this overestimates the wall time of an idle 2-core machine; benchmarks/README.md gives
// the estimate from the profile's parallel fraction beside it.
#pragma once

#include <benchmark/benchmark.h>

#include <ctime>

namespace maquette::bench {

inline double thread_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
}

// Starts at construction; stop() sets state's main_cpu_ms to the CPU time since, per iteration.
class MainThreadCpu {
 public:
  explicit MainThreadCpu(benchmark::State& state) : state_(state), start_(thread_cpu_ms()) {}
  void stop() {
    state_.counters["main_cpu_ms"] =
        benchmark::Counter(thread_cpu_ms() - start_, benchmark::Counter::kAvgIterations);
  }

 private:
  benchmark::State& state_;
  double start_;
};

}  // namespace maquette::bench
