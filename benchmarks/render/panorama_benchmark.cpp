// The whole panorama (formats/render/render_job.h): store -> mesh at the levels the distance needs
// -> z-buffer -> colour and every guide, in memory (the files' encoding is timed apart, in
// BM_WritePanorama). A 1024 x 1024-sample DEM (16 tiles of 256 at level 10, 35 m samples, smooth
// hills up to ~700 m on EGM96 heights, so PROJ's geoid is read per vertex as for SRTM) and an
// RGB texture of the same cells, with their overviews, in a store file made once; seen from 3 km
// above the DEM's edge towards its centre, into 2000 x 2000 (4 MP) and 8000 x 5000 pictures, on 1
// and 2 threads; BM_PanoramaAntialias the 4 MP picture with 2 x 2 and 3 x 3 samples a pixel for its
// colour. BM_PanoramaShadeNoDataCollar: the colour and guides with a texture whose tiles
// hold no data in a collar 320 texels wide round the DEM (render/edge_texels.h's worst case: the
// terrain past the data, inside tiles, far beyond the reach).
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "render/render_job.h"
#include "render/terrain_scene.h"

namespace maquette {
namespace {

constexpr int kLevel = 10, kSize = 256, kTiles = 4, kFace = 1, kCol0 = 300, kRow0 = 500;
constexpr int kCollar = 320;  // texels of no data round the DEM in the texture "rgb_collar"

double height(int64_t col, int64_t row) {  // global sample column and row
  const double x = double(col), y = double(row);
  return 300 + 400 * std::sin(x / 48) * std::cos(y / 65) + 250 * std::sin(y / 26 + x / 88);
}

struct PanoramaStore {
  PanoramaStore() {
    std::filesystem::remove(path);
    auto store = Store::open(path, Store::Mode::Create);
    LayerInfo dem;
    dem.name = "dem";
    dem.level = kLevel;
    dem.tile_size = kSize;
    dem.units = "m";
    dem.provenance["vertical_datum"] = {{"crs", "EPSG:5773"}, {"name", "EGM96 height"}};
    store->create_layer(dem);
    LayerInfo rgb = dem;
    rgb.name = "rgb";
    rgb.dtype = DType::U8;
    rgb.channels = 3;
    rgb.units = "";
    store->create_layer(rgb);
    LayerInfo collar = rgb;
    collar.name = "rgb_collar";
    collar.nodata = 0;
    store->create_layer(collar);
    Store::Batch batch(*store);
    for (int r = 0; r < kTiles; ++r)
      for (int c = 0; c < kTiles; ++c) {
        const CellId cell = CellId::FromFaceColRow(kFace, kLevel, kCol0 + c, kRow0 + r);
        Tile<float> h(kSize, 1);
        Tile<uint8_t> colour(kSize, 3), collared(kSize, 3);
        for (int y = 0; y < kSize; ++y)
          for (int x = 0; x < kSize; ++x) {
            const double z = height(int64_t(kCol0 + c) * kSize + x, int64_t(kRow0 + r) * kSize + y);
            h.at(x, y) = float(z);
            colour.at(x, y, 0) = uint8_t(90 + z / 10);  // never 0, the collar's nodata
            colour.at(x, y, 1) = uint8_t(140 - z / 12);
            colour.at(x, y, 2) = uint8_t(60 + (x ^ y) % 32);
            const int gx = c * kSize + x, gy = r * kSize + y, end = kTiles * kSize - kCollar;
            const bool inside = gx >= kCollar && gx < end && gy >= kCollar && gy < end;
            for (int k = 0; k < 3; ++k) collared.at(x, y, k) = inside ? colour.at(x, y, k) : 0;
          }
        batch.put_tile("dem", cell, from_tile(h, DType::F32));
        batch.put_tile("rgb", cell, from_tile(colour, DType::U8));
        batch.put_tile("rgb_collar", cell, from_tile(collared, DType::U8));
      }
    batch.commit();
    store->update_overviews("dem");
    store->update_overviews("rgb");
    store->update_overviews("rgb_collar");
  }
  ~PanoramaStore() {
    for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(path + suffix);
  }
  std::string path = (std::filesystem::temp_directory_path() /
                      ("maquette-panorama-" + std::to_string(::getpid()) + ".mqt"))
                         .string();
};

PanoramaJob job(int width, int height) {
  const Grid& grid = default_grid();
  // From above the middle of the DEM's first row of cells' outer edge, towards its centre.
  const LonLat eye = grid.centre(CellId::FromFaceColRow(kFace, kLevel, kCol0 + 1, kRow0 - 1));
  const LonLat centre =
      grid.centre(CellId::FromFaceColRow(kFace, kLevel + 1, 2 * kCol0 + 4, 2 * kRow0 + 4));
  PanoramaJob j;
  j.dem = "dem";
  j.texture = "rgb";
  j.camera.eye = {eye.lon, eye.lat, 3000};
  j.look_at = GeodeticPoint{centre.lon, centre.lat, 0};
  j.camera.fov = 70;
  j.camera.width = width;
  j.camera.height = height;
  return j;
}

const PanoramaStore& panorama_store() {
  static const PanoramaStore s;
  return s;
}

void BM_Panorama(benchmark::State& state) {
  const auto store = Store::open(panorama_store().path, Store::Mode::ReadOnly);
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, size_t(state.range(2)));
  const PanoramaJob j = job(int(state.range(0)), int(state.range(1)));
  for (auto _ : state) benchmark::DoNotOptimize(render_panorama(*store, default_grid(), j));
  state.counters["Mpx"] = double(state.range(0) * state.range(1)) / 1e6;
}
BENCHMARK(BM_Panorama)
    ->Args({2000, 2000, 1})
    ->Args({2000, 2000, 2})
    ->Args({8000, 5000, 1})
    ->Args({8000, 5000, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The same with the colour supersampled (render/panorama_supersample.h): K x K samples a pixel.
void BM_PanoramaAntialias(benchmark::State& state) {
  const auto store = Store::open(panorama_store().path, Store::Mode::ReadOnly);
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, size_t(state.range(2)));
  PanoramaJob j = job(int(state.range(0)), int(state.range(1)));
  j.antialias = int(state.range(3));
  for (auto _ : state) benchmark::DoNotOptimize(render_panorama(*store, default_grid(), j));
  state.counters["Mpx"] = double(state.range(0) * state.range(1)) / 1e6;
}
BENCHMARK(BM_PanoramaAntialias)
    ->Args({2000, 2000, 2, 2})
    ->Args({2000, 2000, 2, 3})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The whole panorama's steps apart (one thread): the mesh from the store, the z-buffer, the colour
// and guides.
struct PanoramaSteps {
  std::unique_ptr<Store> store = Store::open(panorama_store().path, Store::Mode::ReadOnly);
  PanoramaJob j;
  LayerInfo dem = *store->layer("dem"), texture;
  PinholeCamera camera;
  PanoramaSteps(int width, int height, const char* texture_layer = "rgb")
      : j(job(width, height)), texture(*store->layer(texture_layer)), camera(aimed(j)) {}
  static CameraSpec aimed(const PanoramaJob& j) {
    CameraSpec spec = j.camera;
    const auto [heading, pitch] = aim(spec.eye, *j.look_at);
    spec.heading = heading;
    spec.pitch = pitch;
    return spec;
  }
  TerrainScene scene() const {
    return build_terrain_scene(*store, default_grid(), dem, camera, 1, 1, true);
  }
  PanoramaLook look() const {
    PanoramaLook l;
    l.texture = &texture;
    return l;
  }
};

// The mesh and the attributes of the vertices the picture shows (those of a scene built apart: the
// same mesh), the z-buffer between them not timed.
void BM_PanoramaMesh(benchmark::State& state) {
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 1);
  const PanoramaSteps steps(int(state.range(0)), int(state.range(1)));
  const Fragments f = rasterize(steps.scene().mesh, steps.camera);
  for (auto _ : state) {
    TerrainScene scene = steps.scene();
    attribute_vertices(scene, &f);
    benchmark::DoNotOptimize(scene);
  }
}
BENCHMARK(BM_PanoramaMesh)->Args({2000, 2000})->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_PanoramaRasterize(benchmark::State& state) {
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 1);
  const PanoramaSteps steps(int(state.range(0)), int(state.range(1)));
  const TerrainScene scene = steps.scene();
  for (auto _ : state) benchmark::DoNotOptimize(rasterize(scene.mesh, steps.camera));
  // What the z-buffer draws for what it shows: the triangles, those some pixel shows, the terrain
  // pixels.
  const Fragments f = rasterize(scene.mesh, steps.camera);
  std::vector<bool> shown(scene.mesh.triangle_count());
  size_t terrain = 0;
  for (const uint32_t t : f.triangle)
    if (t != Fragments::kSky) shown[t] = true, ++terrain;
  state.counters["triangles"] = double(scene.mesh.triangle_count());
  state.counters["shown"] = double(std::count(shown.begin(), shown.end(), true));
  state.counters["terrain_px"] = double(terrain);
}
BENCHMARK(BM_PanoramaRasterize)->Args({2000, 2000})->Unit(benchmark::kMillisecond)->UseRealTime();

// The colour and guides of the 4 MP picture's fragments, `texture` draped.
void shade(benchmark::State& state, const char* texture) {
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 1);
  const PanoramaSteps steps(int(state.range(0)), int(state.range(1)), texture);
  TerrainScene scene = steps.scene();
  const Fragments f = rasterize(scene.mesh, steps.camera);
  attribute_vertices(scene, &f);
  const PanoramaLook look = steps.look();
  const int rows = steps.camera.spec().height;  // the fragments of the whole picture at once
  for (auto _ : state)
    benchmark::DoNotOptimize(shade_panorama(*steps.store, default_grid(), scene, steps.camera, look,
                                            rows, [&](int, int) -> const Fragments& { return f; }));
}

void BM_PanoramaShade(benchmark::State& state) { shade(state, "rgb"); }
BENCHMARK(BM_PanoramaShade)->Args({2000, 2000})->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_PanoramaShadeNoDataCollar(benchmark::State& state) { shade(state, "rgb_collar"); }
BENCHMARK(BM_PanoramaShadeNoDataCollar)
    ->Args({2000, 2000})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_WritePanorama(benchmark::State& state) {
  const auto store = Store::open(panorama_store().path, Store::Mode::ReadOnly);
  const Panorama p = render_panorama(*store, default_grid(), job(2000, 2000));
  const std::string out = panorama_store().path + ".png";
  for (auto _ : state) write_panorama(p, out);
  std::filesystem::path stem(out);
  stem.replace_extension();
  for (const std::string& f :
       {out, stem.string() + "-guides.tif", stem.string() + "-silhouettes.png"})
    std::filesystem::remove(f);
}
BENCHMARK(BM_WritePanorama)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace maquette

BENCHMARK_MAIN();
