// deform.water's water body (level + fill, water_body.h) for a 1,000 x 1,000-sample basin: the
// hills of a bowl (islands, a ragged shore) inside an ellipse, filled to the spill level. Goal:
// <= 50 ms. With --dem=PATH it writes that DEM as a GeoTIFF (UTM zone 12, 30 m) and prints the
// level and seed for compare_rlake.sh, then exits.
#include <benchmark/benchmark.h>
#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>

#include "water_body.h"

namespace {

using maquette::deform::BasinRaster;

constexpr int kSide = 1000;
constexpr double kPixelM = 30, kX0 = 300000, kY0 = 4100000;

struct Basin {
  std::vector<float> terrain;
  std::vector<uint8_t> inside;
  BasinRaster raster() const { return {kSide, kSide, terrain, inside, kPixelM * kPixelM}; }
};

const Basin& basin() {
  static const Basin b = [] {
    Basin b;
    for (int r = 0; r < kSide; ++r)
      for (int c = 0; c < kSide; ++c) {
        const double x = (c + 0.5) * kPixelM, y = (r + 0.5) * kPixelM;
        const double u = (c - 500) / 450.0, v = (r - 500) / 400.0;
        b.terrain.push_back(float(1000 + 60 * (u * u + v * v) +
                                  15 * std::sin(x / 300) * std::cos(y / 410) +
                                  8 * std::sin((x + 2 * y) / 170)));
        b.inside.push_back(u * u + v * v <= 1);
      }
    return b;
  }();
  return b;
}

void BM_WaterBody(benchmark::State& state) {
  const BasinRaster raster = basin().raster();
  size_t wet = 0;
  for (auto _ : state) {
    const auto body =
        maquette::deform::fill_basin(raster, maquette::deform::water_level(raster, {}));
    wet = body.wet.size();
    benchmark::DoNotOptimize(body.volume_m3);
  }
  state.counters["wet"] = double(wet);
}
BENCHMARK(BM_WaterBody)->Unit(benchmark::kMillisecond);

// Writes the basin as a GeoTIFF and prints "LEVEL X Y" (the spill level and the seed's centre).
int write_dem(const char* path) {
  GDALAllRegister();
  const std::unique_ptr<GDALDataset> ds(GetGDALDriverManager()->GetDriverByName("GTiff")->Create(
      path, kSide, kSide, 1, GDT_Float32, nullptr));
  double transform[6] = {kX0, kPixelM, 0, kY0, 0, -kPixelM};
  ds->SetGeoTransform(transform);
  OGRSpatialReference srs;
  srs.importFromEPSG(32612);
  ds->SetSpatialRef(&srs);
  auto& terrain = const_cast<std::vector<float>&>(basin().terrain);
  if (ds->GetRasterBand(1)->RasterIO(GF_Write, 0, 0, kSide, kSide, terrain.data(), kSide, kSide,
                                     GDT_Float32, 0, 0) != CE_None)
    return 1;
  const BasinRaster raster = basin().raster();
  const double level = maquette::deform::water_level(raster, {});
  const auto body = maquette::deform::fill_basin(raster, level);
  std::printf("%.9g %.3f %.3f\n", level, kX0 + (double(body.seed % kSide) + 0.5) * kPixelM,
              kY0 - (double(body.seed / kSide) + 0.5) * kPixelM);
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
