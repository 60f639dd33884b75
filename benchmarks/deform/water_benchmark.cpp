// deform.water's water body (level + fill, water_body.h), its closed mesh (water_mesh.h: a
// flat bottom under the terrain), its fog volume straight from the depth raster
// (water_columns.h, vdb/column_fog.h) and the mesh's store blob for a 1,000 x 1,000-sample basin:
// the tests' bowl of hills (islands, a ragged shore) inside an ellipse, filled to the spill level.
// Goals: <= 50 ms for the body, well under a second for the mesh. With --dem=PATH it writes that
// DEM as a GeoTIFF and prints the level and the seed's coordinates for compare_rlake.sh (r.lake on
// the same DEM), then exits.
#include <benchmark/benchmark.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <cstdio>
#include <cstring>

#include "content/facet_normals.h"
#include "core/parallel_chunks.h"
#include "gltf/mesh_glb.h"
#include "main_thread_cpu.h"
#include "tests/water_basins.h"
#include "vdb/column_fog.h"
#include "water_columns.h"
#include "water_content.h"
#include "water_mesh.h"

namespace {

using namespace maquette::deform;

const Basin& basin() {
  static const Basin b = hills(1000, 1000);
  return b;
}

void BM_WaterBody(benchmark::State& state) {
  const BasinRaster raster = basin().raster();
  size_t wet = 0;
  maquette::bench::MainThreadCpu main_cpu(state);
  for (auto _ : state) {
    const WaterBody body = fill_basin(raster, water_level(raster, {}));
    wet = body.wet.size();
    benchmark::DoNotOptimize(body.volume_m3);
  }
  main_cpu.stop();
  state.counters["wet"] = double(wet);
}
BENCHMARK(BM_WaterBody)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();

// The lake's closed mesh (its flat bottom under the terrain).
void BM_LakeMesh(benchmark::State& state) {
  const BasinRaster raster = basin().raster();
  const WaterBody body = fill_basin(raster, water_level(raster, {}));
  const double bottom = lake_flat_bottom(raster, body);
  size_t triangles = 0;
  maquette::bench::MainThreadCpu main_cpu(state);
  for (auto _ : state) {
    const LakeMesh mesh = lake_mesh(raster, body, bottom);
    triangles = mesh.indices.size() / 3;
    benchmark::DoNotOptimize(mesh.vertices.data());
  }
  main_cpu.stop();
  state.counters["wet"] = double(body.wet.size());
  state.counters["triangles"] = double(triangles);
}
BENCHMARK(BM_LakeMesh)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();

// The lake's mesh in a plane frame (col, -row scaled to metres).
maquette::MeshObject plane_mesh(const LakeMesh& mesh) {
  maquette::MeshObject object;
  for (const LakeVertex& v : mesh.vertices)
    object.positions.insert(object.positions.end(),
                            {float(v.col * kPixelM), float(-v.row * kPixelM), float(v.height)});
  object.indices = mesh.indices;
  return object;
}

// The lake's fog columns as deform.water builds them (water_content.h: a column per wet pixel,
// voxels of a pixel across, the greatest depth over kVoxelsDeep high), in the plane frame of
// plane_mesh (pixel centres at (col + 1/2, -(row + 1/2)) pixels), the surface flat, its places
// made in parallel as LakeContent::fog makes them.
maquette::FogColumns plane_columns(const BasinRaster& raster, const WaterBody& body) {
  const auto centre = [&](int64_t pixel) {
    return std::array{(double(pixel % raster.width) + 0.5) * kPixelM,
                      -(double(pixel / raster.width) + 0.5) * kPixelM, body.level};
  };
  const PixelLattice lattice{centre(body.seed), {kPixelM, 0, 0}, {0, -kPixelM, 0}};
  std::vector<std::array<double, 3>> surface(body.wet.size());
  maquette::parallel_chunks(surface.size(), 4096, [&](size_t first, size_t last) {
    for (size_t w = first; w < last; ++w) surface[w] = centre(body.wet[w]);
  });
  return lake_columns(raster, body, lattice, surface, LakeContent::kVoxelsDeep);
}

// The fog volume from the depth raster: the columns, and columns_to_fog as the volume plug-in
// runs it.
void BM_LakeVolume(benchmark::State& state) {
  const BasinRaster raster = basin().raster();
  const WaterBody body = fill_basin(raster, water_level(raster, {}));
  size_t bytes = 0;
  maquette::bench::MainThreadCpu main_cpu(state);
  for (auto _ : state)
    bytes = maquette::columns_to_fog({plane_columns(raster, body)}, {}, "lake").vdb.size();
  main_cpu.stop();
  state.counters["wet"] = double(body.wet.size());
  state.counters["MB"] = double(bytes) / 1e6;
}
BENCHMARK(BM_LakeVolume)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();

// The lake's flat-bottomed mesh with its facet normals, as the mesh port gets it
// (content/facet_normals.h).
void BM_LakeMeshNormals(benchmark::State& state) {
  const BasinRaster raster = basin().raster();
  const WaterBody body = fill_basin(raster, water_level(raster, {}));
  const maquette::MeshObject mesh =
      plane_mesh(lake_mesh(raster, body, lake_flat_bottom(raster, body)));
  size_t vertices = 0;
  maquette::bench::MainThreadCpu main_cpu(state);
  for (auto _ : state) vertices = maquette::with_facet_normals(mesh).positions.size() / 3;
  main_cpu.stop();
  state.counters["vertices"] = double(vertices);
}
BENCHMARK(BM_LakeMeshNormals)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();

// The lake's mesh with its normals and material as the store's blob (gltf/mesh_glb.h: the GLB,
// Draco-compressed, that the runner writes for the mesh port): what the program does with the
// mesh after the step.
void BM_LakeMeshBlob(benchmark::State& state) {
  const BasinRaster raster = basin().raster();
  const WaterBody body = fill_basin(raster, water_level(raster, {}));
  maquette::MeshContent content;
  content.materials.emplace_back().name = "water";  // its factors do not change the work
  content.objects.push_back(maquette::with_facet_normals(
      plane_mesh(lake_mesh(raster, body, lake_flat_bottom(raster, body)))));
  content.objects.back().material = 0;
  size_t bytes = 0;
  maquette::bench::MainThreadCpu main_cpu(state);
  for (auto _ : state) bytes = maquette::mesh_content_blob(content).size();
  main_cpu.stop();
  state.counters["MB"] = double(bytes) / 1e6;
}
BENCHMARK(BM_LakeMeshBlob)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();

// The whole water body as deform.water makes it: level, fill, then the flat-bottomed mesh with its
// normals beside the fog volume from the depth raster, as LakeContent::finish makes them (the goal:
// <= 50 ms on 2 cores).
void BM_WaterBodyWhole(benchmark::State& state) {
  const BasinRaster raster = basin().raster();
  maquette::bench::MainThreadCpu main_cpu(state);
  for (auto _ : state) {
    const WaterBody body = fill_basin(raster, water_level(raster, {}));
    const double bottom = lake_flat_bottom(raster, body);
    tbb::parallel_invoke(
        [&] {
          const maquette::MeshObject shown = plane_mesh(lake_mesh(raster, body, bottom));
          benchmark::DoNotOptimize(maquette::with_facet_normals(shown).normals.data());
        },
        [&] {
          benchmark::DoNotOptimize(
              maquette::columns_to_fog({plane_columns(raster, body)}, {}, "lake").vdb.data());
        });
  }
  main_cpu.stop();
}
BENCHMARK(BM_WaterBodyWhole)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();

// Writes the basin as a GeoTIFF and prints "LEVEL X Y" (the spill level, the seed's centre).
int write_dem(const char* path) {
  if (!write_geotiff(basin(), path)) return 1;
  const BasinRaster raster = basin().raster();
  const double level = water_level(raster, {});
  const WaterBody body = fill_basin(raster, level);
  const int width = basin().width;
  std::printf("%.9g %.3f %.3f\n", level, kX0 + (double(body.seed % width) + 0.5) * kPixelM,
              kY0 - (double(body.seed / width) + 0.5) * kPixelM);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (std::strncmp(argv[i], "--dem=", 6) == 0) return write_dem(argv[i] + 6);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  return 0;
}
