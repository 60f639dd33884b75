// The painting fit (formats/render/painting_fit.h): a camera with an unknown focal length from 15
// clicks, and a camera with the progressive bend from 30 clicks, on a 1600 x 1000 painting of
// hills 5-55 km from the eye, each click off by 2 px (root mean square). The goal: a solve
// in <= 50 ms.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "render/painting_fit.h"

namespace maquette {
namespace {

double hills(double lon, double lat) {
  return 400 + 900 * std::pow(std::sin(lon * 37) * std::cos(lat * 29), 2) +
         300 * std::sin(lon * 113 + lat * 71);
}

PaintingFitOptions options(bool bend) {
  PaintingFitOptions o;
  o.width = 1600;
  o.height = 1000;
  o.bend = bend;
  o.ground_height = [](LonLat p) { return hills(p.lon, p.lat); };
  return o;
}

// `count` clicks of ground points that the camera (and bend) draw inside the painting.
std::vector<GroundClick> clicks(size_t count, bool bend) {
  CameraSpec camera{{10.2, 44.9, 2000}, 5, -6, 60, 1600, 1000};
  ProgressiveBend warp;
  if (bend) warp = {35000, 6000, hills(10.2, 44.9) - 2000};
  std::mt19937 random(1);
  std::uniform_real_distribution<double> lon(9.9, 10.5), lat(44.93, 45.45);
  std::normal_distribution<double> noise(0, std::sqrt(2.0));
  std::vector<GroundClick> out;
  while (out.size() < count) {
    GeodeticPoint g{lon(random), lat(random), 0};
    g.height = hills(g.lon, g.lat);
    const auto p = project_ground(camera, warp, {g})[0];
    if (!(p[0] >= 0 && p[0] <= 1600 && p[1] >= 0 && p[1] <= 1000)) continue;
    out.push_back({p[0] + noise(random), p[1] + noise(random), g});
  }
  return out;
}

void BM_FitPlainPainting(benchmark::State& state) {
  const auto c = clicks(15, false);
  const auto o = options(false);
  for (auto _ : state) benchmark::DoNotOptimize(fit_painting(c, o));
}
BENCHMARK(BM_FitPlainPainting)->Unit(benchmark::kMillisecond);

void BM_FitBentPainting(benchmark::State& state) {
  const auto c = clicks(30, true);
  auto o = options(true);
  o.warp_smoothing = 0.001;
  for (auto _ : state) benchmark::DoNotOptimize(fit_painting(c, o));
}
BENCHMARK(BM_FitBentPainting)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace maquette

BENCHMARK_MAIN();
