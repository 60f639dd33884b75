// The rasterizer of panoramas (formats/render/rasterizer.h): a 1000 x 1000-sample terrain (30 m
// apart, ~2 M triangles, smooth hills up to ~1 km) seen obliquely from 3 km up, into a 2000 x
// 2000 picture (4 MP), on 1 and 2 threads. `render_benchmark --write-mesh=FILE` writes that mesh
// in the camera's frame instead, for osmesa_render.c (osmesa_side_by_side.sh): int32 width,
// height, vertex and triangle counts, float64 focal length, then float32 x, y, z per vertex (x
// right, y down, z forward, metres) and uint32 indices, 3 per triangle, little-endian.
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>

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

PinholeCamera benchmark_camera() {
  CameraSpec spec;
  spec.eye = {-112.95, 37.25, 3000};
  spec.pitch = -15;
  spec.fov = 70;
  spec.width = spec.height = 2000;
  return PinholeCamera(spec);
}

void write_mesh(const std::string& path) {
  const RenderMesh mesh = hills(1000, 30);
  const PinholeCamera camera = benchmark_camera();
  std::ofstream out(path, std::ios::binary);
  const int32_t header[4] = {camera.spec().width, camera.spec().height,
                             int32_t(mesh.positions.size() / 3), int32_t(mesh.triangle_count())};
  const double focal = camera.focal();
  out.write(reinterpret_cast<const char*>(header), sizeof header);
  out.write(reinterpret_cast<const char*>(&focal), sizeof focal);
  for (size_t i = 0; i < mesh.positions.size(); i += 3) {
    const Vec3d v =
        camera.to_view({mesh.positions[i], mesh.positions[i + 1], mesh.positions[i + 2]});
    const float xyz[3] = {float(v[0]), float(v[1]), float(v[2])};
    out.write(reinterpret_cast<const char*>(xyz), sizeof xyz);
  }
  out.write(reinterpret_cast<const char*>(mesh.indices.data()),
            std::streamsize(mesh.indices.size() * sizeof(uint32_t)));
  if (!out) throw std::runtime_error("cannot write " + path);
}

void BM_Rasterize(benchmark::State& state) {
  static const RenderMesh mesh = hills(1000, 30);
  const PinholeCamera camera = benchmark_camera();
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, size_t(state.range(0)));
  size_t drawn = 0;
  for (auto _ : state) {
    const Fragments f = rasterize(mesh, camera);
    drawn = size_t(std::count_if(f.triangle.begin(), f.triangle.end(),
                                 [](uint32_t t) { return t != Fragments::kSky; }));
  }
  state.counters["triangles"] = double(mesh.triangle_count());
  state.counters["drawn"] = double(drawn);  // pixels showing terrain
}
BENCHMARK(BM_Rasterize)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace maquette

int main(int argc, char** argv) {
  constexpr const char* kWriteMesh = "--write-mesh=";
  if (argc == 2 && std::strncmp(argv[1], kWriteMesh, std::strlen(kWriteMesh)) == 0) {
    maquette::write_mesh(argv[1] + std::strlen(kWriteMesh));
    return 0;
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
