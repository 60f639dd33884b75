// The rasterizer of panoramas (formats/render/rasterizer.h): a 1000 x 1000-sample terrain (30 m
// apart, ~2 M triangles, smooth hills up to ~1 km) seen obliquely from 3 km up, into a 2000 x
// 2000 picture (4 MP), on 1 and 2 threads.
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <cmath>

#include "render/rasterizer.h"

namespace maquette {
namespace {

RenderMesh hills(int samples, double spacing) {
  RenderMesh m;
  for (int r = 0; r < samples; ++r)
    for (int c = 0; c < samples; ++c) {
      const double x = (c - samples / 2) * spacing, y = 2000 + r * spacing;
      const double z =
          400 * std::sin(x / 1700) * std::cos(y / 2300) + 300 * std::sin(y / 900 + x / 3100);
      m.positions.insert(m.positions.end(), {x, y, z - 3000});
    }
  for (int r = 0; r + 1 < samples; ++r)
    for (int c = 0; c + 1 < samples; ++c) {
      const auto a = uint32_t(r * samples + c), b = a + 1, d = a + uint32_t(samples), e = d + 1;
      m.indices.insert(m.indices.end(), {a, b, e, a, e, d});
    }
  return m;
}

void BM_Rasterize(benchmark::State& state) {
  static const RenderMesh mesh = hills(1000, 30);
  CameraSpec spec;
  spec.eye = {-112.95, 37.25, 3000};
  spec.pitch = -15;
  spec.fov = 70;
  spec.width = spec.height = 2000;
  const PinholeCamera camera(spec);
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, size_t(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(rasterize(mesh, camera));
  state.counters["triangles"] = double(mesh.triangle_count());
}
BENCHMARK(BM_Rasterize)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace maquette

BENCHMARK_MAIN();
