// deform.features on a 1 M-sample region (1024 x 1024 samples of ~1.2 m near Zion, a sinusoidal
// terrain): one river 1 km long, its bed 5 m below the draped curve, banks 28 m on each side, so
// about 40,000 unknowns in the cross sections' solve (the issue's "one feature edit on a 1 M-sample
// region"). Times the whole step as the runner calls it, without reading or writing the store.
#include <benchmark/benchmark.h>

#include <GeographicLib/LocalCartesian.hpp>
#include <cmath>
#include <numbers>

#include "core/halo.h"
#include "operators.h"

namespace {

using namespace maquette;

constexpr int kCellLevel = 13, kSide = 1024, kPixelLevel = kCellLevel + 10;

struct Scene {
  Mosaic input, output;
  VectorFeature river;
};

Scene make_scene() {
  const CellId cell = default_grid().cell_from_point({-113.0, 37.2}, kCellLevel);
  const LonLat site = default_grid().centre(cell);
  const GeographicLib::LocalCartesian plane(site.lat, site.lon, 0);
  Scene s;
  s.input.face = cell.face();
  s.input.level = kPixelLevel;
  s.input.origin_col = int64_t(cell.col()) * kSide;
  s.input.origin_row = int64_t(cell.row()) * kSide;
  Tile<float> dem(kSide, 1);
  for (int r = 0; r < kSide; ++r)
    for (int c = 0; c < kSide; ++c) {
      const LonLat p =
          pixel_centre(default_grid(),
                       {s.input.face, s.input.origin_col + c, s.input.origin_row + r}, kPixelLevel);
      double e = 0, n = 0, u = 0;
      plane.Forward(p.lat, p.lon, 0, e, n, u);
      dem.at(c, r) = float(1500 + 3 * std::sin(2 * std::numbers::pi * e / 80) *
                                      std::cos(2 * std::numbers::pi * n / 110));
    }
  s.input.layers.emplace("dem", std::move(dem));
  s.output = s.input;
  s.output.layers.at("dem") = Tile<float>(kSide, 1, 0, NAN);

  auto lonlat = [&](double e, double n) {
    double lat = 0, lon = 0, h = 0;
    plane.Reverse(e, n, 0, lat, lon, h);
    return GeoPoint{lon, lat};
  };
  const double heading = 30 * std::numbers::pi / 180;
  s.river.id = 1;
  s.river.geometry.type = GeometryType::LineString;
  s.river.geometry.lines = {{lonlat(-433, -250), lonlat(-433 + 1000 * std::cos(heading),
                                                        -250 + 1000 * std::sin(heading))}};
  s.river.attributes = {{"tool", "feature"},
                        {"cross_section", {{-28, 0}, {-8, -5}, {8, -5}, {28, 0}}}};
  return s;
}

void one_feature_edit(benchmark::State& state) {
  Scene s = make_scene();
  s.input.features["strokes"] = {&s.river};  // the copy's own feature
  const json params = {{"energy_weight", 0.01}};
  const auto op = deform::make_features();
  const auto& region = static_cast<const RegionOperator&>(*op);
  for (auto _ : state) {
    region.run({&default_grid(), &params, nullptr}, s.input, s.output);
    benchmark::DoNotOptimize(s.output.layers.at("dem").data());
  }
}

BENCHMARK(one_feature_edit)->Name("DeformFeatures1MSamples")->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
