// Loop subdivision of a 200 x 200 height field (30 m samples, 6 km), 1 to 3 levels: uniform
// (every triangle, with its matrices) and adaptive near a 1 km feature (triangles within 60 m);
// adaptive also on 1000 x 1000 samples (the 1 M-sample region), 3 levels.
#include <benchmark/benchmark.h>

#include <cmath>

#include "loop_adaptive.h"
#include "loop_marking.h"
#include "loop_subdivision.h"

namespace {

using namespace maquette::deform;

TriangleMesh height_field(int samples) {
  RegularHeightField field{samples, samples, 30.0, 30.0, {}};
  for (int r = 0; r < field.rows; ++r) {
    for (int c = 0; c < field.columns; ++c) {
      field.heights.push_back(1500.0 + 80.0 * std::sin(c / 23.0) * std::cos(r / 15.0));
    }
  }
  return height_field_mesh(field);
}

void uniform(benchmark::State& state) {
  const TriangleMesh base = height_field(200);
  std::size_t triangles = 0;
  for (auto _ : state) {
    TriangleMesh mesh = base;
    for (int level = 0; level < state.range(0); ++level) mesh = loop_subdivide(mesh).mesh;
    triangles = mesh.triangles.size();
    benchmark::DoNotOptimize(mesh.vertices.data());
  }
  state.counters["triangles"] = static_cast<double>(triangles);
}

// state.range(0): levels; state.range(1): samples a side (the feature in the middle).
void adaptive(benchmark::State& state) {
  const TriangleMesh base = height_field(static_cast<int>(state.range(1)));
  const Eigen::Vector2d centre = Eigen::Vector2d::Constant(15.0 * (state.range(1) - 1));
  const Eigen::Vector2d half(500.0 * std::cos(0.4), 500.0 * std::sin(0.4));
  const std::vector<Eigen::Vector2d> feature{centre - half, centre + half};
  std::size_t triangles = 0;
  for (auto _ : state) {
    const AdaptiveLoop result = adaptive_loop_subdivide(
        base, triangles_near_polyline(base, feature, 60.0), static_cast<int>(state.range(0)));
    triangles = result.meshes.back().triangles.size();
    benchmark::DoNotOptimize(result.meshes.back().vertices.data());
  }
  state.counters["triangles"] = static_cast<double>(triangles);
}

BENCHMARK(uniform)->Name("LoopUniform200x200")->DenseRange(1, 3)->Unit(benchmark::kMillisecond);
BENCHMARK(adaptive)
    ->Name("LoopAdaptive")
    ->ArgsProduct({{1, 2, 3}, {200}})
    ->Args({3, 1000})
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
