// Point -> cell at level 20 for random points: RHealpixGrid (single and batched) against libs2's
// S2CellId and against PROJ's rhealpix forward projection alone.
#include <benchmark/benchmark.h>
#include <proj.h>
#include <s2/s2cell_id.h>
#include <s2/s2latlng.h>

#include <cmath>
#include <random>
#include <vector>

#include "rhealpix/rhealpix_grid.h"

namespace maquette {
namespace {

constexpr int kLevel = 20;
constexpr size_t kPoints = size_t(1) << 16;

const std::vector<LonLat>& points() {
  static const std::vector<LonLat> out = [] {
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> lon(-180, 180), z(-1, 1);
    std::vector<LonLat> p(kPoints);
    for (auto& q : p) q = {lon(rng), std::asin(z(rng)) * 180 / M_PI};
    return p;
  }();
  return out;
}

void BM_RHealpixCellFromPoint(benchmark::State& state) {
  const RHealpixGrid grid;
  const auto& p = points();
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(grid.cell_from_point(p[i], kLevel));
    i = (i + 1) & (kPoints - 1);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_RHealpixCellFromPoint);

void BM_RHealpixCellsFromPoints(benchmark::State& state) {
  const RHealpixGrid grid;
  const auto& p = points();
  std::vector<CellId> out(p.size());
  for (auto _ : state) {
    grid.cells_from_points(p, kLevel, out);
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * int64_t(p.size()));
}
BENCHMARK(BM_RHealpixCellsFromPoints);

void BM_S2CellId(benchmark::State& state) {
  const auto& p = points();
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(S2CellId(S2LatLng::FromDegrees(p[i].lat, p[i].lon)).parent(kLevel));
    i = (i + 1) & (kPoints - 1);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_S2CellId);

void BM_ProjForward(benchmark::State& state) {
  PJ_CONTEXT* ctx = proj_context_create();
  PJ* pj = proj_create(ctx, "+proj=rhealpix +ellps=WGS84 +north_square=0 +south_square=0");
  const auto& p = points();
  constexpr double kDeg = M_PI / 180;
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        proj_trans(pj, PJ_FWD, proj_coord(p[i].lon * kDeg, p[i].lat * kDeg, 0, 0)));
    i = (i + 1) & (kPoints - 1);
  }
  state.SetItemsProcessed(state.iterations());
  proj_destroy(pj);
  proj_context_destroy(ctx);
}
BENCHMARK(BM_ProjForward);

}  // namespace
}  // namespace maquette

BENCHMARK_MAIN();
