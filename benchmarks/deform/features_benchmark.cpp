// deform.features on a sinusoidal terrain near Zion (samples of ~1.2 m): a 1 M-sample region
// (1024 x 1024) with one river 1 km long, its bed (the curve) 5 m below the terrain under it, banks
// 28 m on each side, so about 40,000 unknowns in the cross sections' solve (the issue's "one
// feature edit on a 1 M-sample region"); and the refined edits (1 to 3 levels finer) of a 150 m
// river, banks 20 m on each side, on a 256 x 256 region. Times the whole step as the runner calls
// it, without reading or writing the store.
#include <benchmark/benchmark.h>

#include <GeographicLib/LocalCartesian.hpp>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/halo.h"
#include "main_thread_cpu.h"
#include "operators.h"

namespace {

using namespace maquette;

struct Scene {
  Mosaic input, output;
  VectorFeature river;
};

// The sinusoidal terrain's height at (e, n) metres of the site's tangent plane.
double terrain(double e, double n) {
  return 1500 +
         3 * std::sin(2 * std::numbers::pi * e / 80) * std::cos(2 * std::numbers::pi * n / 110);
}

// A region of side x side samples of ~1.2 m (pixel level 23) and a river `length` m long, its
// banks `bank` m from the curve, output `refine` levels finer.
Scene make_scene(int side, double length, double bank, int refine) {
  const int pixel_level = 23, cell_level = pixel_level - int(std::log2(side));
  const CellId cell = default_grid().cell_from_point({-113.0, 37.2}, cell_level);
  const LonLat site = default_grid().centre(cell);
  const GeographicLib::LocalCartesian plane(site.lat, site.lon, 0);
  Scene s;
  s.input.face = cell.face();
  s.input.level = pixel_level;
  s.input.origin_col = int64_t(cell.col()) * side;
  s.input.origin_row = int64_t(cell.row()) * side;
  Tile<float> dem(side, 1);
  for (int r = 0; r < side; ++r)
    for (int c = 0; c < side; ++c) {
      const LonLat p =
          pixel_centre(default_grid(),
                       {s.input.face, s.input.origin_col + c, s.input.origin_row + r}, pixel_level);
      double e = 0, n = 0, u = 0;
      plane.Forward(p.lat, p.lon, 0, e, n, u);
      dem.at(c, r) = float(terrain(e, n));
    }
  s.input.layers.emplace("dem", std::move(dem));
  s.output = s.input;
  s.output.level += refine;
  s.output.layers.at("dem") = Tile<float>(side << refine, 1, 0, NAN);

  auto lonlat = [&](double e, double n) {
    double lat = 0, lon = 0, h = 0;
    plane.Reverse(e, n, 0, lat, lon, h);
    return GeoPoint{lon, lat};
  };
  const double heading = 30 * std::numbers::pi / 180;
  s.river.id = 1;
  s.river.geometry.type = GeometryType::LineString;
  const double e0 = -0.433 * length, n0 = -0.25 * length;  // centred on the site
  s.river.geometry.lines = {
      {lonlat(e0, n0), lonlat(e0 + length * std::cos(heading), n0 + length * std::sin(heading))}};
  // The curve is the bed, 5 m below the terrain under it (a profile every metre), the banks at
  // the terrain's height (dz 5 m): the curve's elevation holds at offset 0.
  json profile = json::array();
  for (double d = 0; d < length + 1; d += 1) {
    const double along = std::min(d, length);
    profile.push_back(
        {along, terrain(e0 + along * std::cos(heading), n0 + along * std::sin(heading)) - 5});
  }
  s.river.attributes = {
      {"tool", "feature"},
      {"profile", profile},
      {"cross_section", {{-bank, 5}, {-0.3 * bank, 0}, {0.3 * bank, 0}, {bank, 5}}}};
  return s;
}

// state.range: samples a side, river length (m), bank offset (m), refine.
void one_feature_edit(benchmark::State& state) {
  Scene s = make_scene(int(state.range(0)), double(state.range(1)), double(state.range(2)),
                       int(state.range(3)));
  s.input.features["strokes"] = {&s.river};  // the copy's own feature
  const json params = {{"energy_weight", 0.01}, {"subdivision", "adaptive"}};  // the defaults
  const auto op = deform::make_features();
  const auto& region = static_cast<const RegionOperator&>(*op);
  maquette::bench::MainThreadCpu main_cpu(state);
  for (auto _ : state) {
    region.run({&default_grid(), &params, nullptr}, s.input, s.output);
    benchmark::DoNotOptimize(s.output.layers.at("dem").data());
  }
  main_cpu.stop();
}

BENCHMARK(one_feature_edit)
    ->Name("DeformFeatures")
    ->Args({1024, 1000, 28, 0})
    ->Args({256, 150, 20, 1})
    ->Args({256, 150, 20, 2})
    ->Args({256, 150, 20, 3})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime();

}  // namespace

BENCHMARK_MAIN();
