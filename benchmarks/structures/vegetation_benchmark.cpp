// Plants placed per second on one core (issue 17: >= 1 M/s): poisson_disk over a square of
// 1,000 x 1,000 spacings (1 M plants) asked as one window and as 64 tiles (each with its
// dependency halo, as cells ask for it), the paper's random placement for comparison, and the
// whole operator on one cell (placement, then each plant on the ground: its cell, height, colour,
// look and rotation).
#include <benchmark/benchmark.h>

#include <GeographicLib/LocalCartesian.hpp>

#include "operators.h"
#include "poisson_disk.h"
#include "vegetation_random.h"

namespace {

using maquette::PolygonSet;
using namespace maquette::structures;

constexpr double kSpacing = 2, kSide = 2000;  // 1 M plants

const PolygonSet& square() {
  static const PolygonSet s({{{{0, 0}, {kSide, 0}, {kSide, kSide}, {0, kSide}, {0, 0}}}});
  return s;
}

void BM_PoissonDisk(benchmark::State& state) {
  const int tiles = int(state.range(0));  // per side
  const double r = poisson_min_distance(kSpacing), step = kSide / tiles;
  size_t plants = 0;
  for (auto _ : state)
    for (int j = 0; j < tiles; ++j)
      for (int i = 0; i < tiles; ++i) {
        const auto points =
            poisson_disk(square(), r, 1, {i * step, j * step, (i + 1) * step, (j + 1) * step});
        plants += points.size();
        benchmark::DoNotOptimize(points.data());
      }
  state.SetItemsProcessed(int64_t(plants));
}
BENCHMARK(BM_PoissonDisk)->Arg(1)->Arg(8)->Unit(benchmark::kMillisecond);

void BM_RandomPlacement(benchmark::State& state) {
  const Footprint polygon = make_footprint({{{0, 0}, {kSide, 0}, {kSide, kSide}, {0, kSide}}});
  size_t plants = 0;
  for (auto _ : state) {
    const auto points = random_placement(polygon, kSpacing, 1);
    plants += points.size();
    benchmark::DoNotOptimize(points.data());
  }
  state.SetItemsProcessed(int64_t(plants));
}
BENCHMARK(BM_RandomPlacement)->Unit(benchmark::kMillisecond);

// structures.vegetation on a cell of level 12 (~2.4 km) inside a square stroke of spacing 3 m.
void BM_VegetationCell(benchmark::State& state) {
  using namespace maquette;
  const Grid& grid = default_grid();
  const int tile_size = 64;
  const CellId cell = grid.cell_from_point({-112, 37}, 12);
  const LonLat c = grid.centre(cell);
  const GeographicLib::LocalCartesian frame(c.lat, c.lon, 0);
  GeoPath ring;
  for (const auto& [x, y] :
       {std::pair(-2e3, -2e3), {2e3, -2e3}, {2e3, 2e3}, {-2e3, 2e3}, {-2e3, -2e3}}) {
    double lat = 0, lon = 0, h = 0;
    frame.Reverse(x, y, 0, lat, lon, h);
    ring.push_back({lon, lat});
  }
  VectorFeature stroke;
  stroke.id = 1;
  stroke.geometry.type = GeometryType::Polygon;
  stroke.geometry.polygons = {{{ring}}};
  stroke.attributes = {{"tool", "vegetation"}, {"spacing_m", 3}};
  const json params = {{"placement", "poisson"},
                       {"seed", 0},
                       {"prototypes", {{{"name", "builtin:broadleaf"}, {"weight", 1}}}},
                       {"scale", {8, 15}},
                       {"heading_deg", {0, 360}}};
  const InputLayers layers = {{"dem", LayerInfo{}}, {"orthophoto", LayerInfo{}}};  // ellipsoidal
  CellContext ctx;
  ctx.input_layers = &layers;
  ctx.cell = cell;
  ctx.tile_size = tile_size;
  ctx.grid = &grid;
  ctx.params = &params;
  const auto op = structures::make_vegetation();
  size_t plants = 0;
  for (auto _ : state) {
    CellData data;
    data.inputs.emplace("dem", Tile<float>(tile_size, 1, 1, 1000.0f));
    data.inputs.emplace("orthophoto", Tile<float>(tile_size, 3, 1, 90.0f));
    data.features["strokes"] = {&stroke};
    data.content.instances["plants"].origin = {c.lon, c.lat, 0};
    static_cast<const CellOperator&>(*op).run(ctx, data);
    plants += data.content.instances["plants"].size();
  }
  state.SetItemsProcessed(int64_t(plants));
}
BENCHMARK(BM_VegetationCell)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
