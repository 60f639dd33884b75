// synthesis.inpaint's completion (modules/synthesis/inpaint.h) beside OpenCV xphoto's shift-map
// and FSR fills, on the same 1000 x 1000 window of Zion's Landsat 8 RGB (../shared/data) and the
// same centred square holes of 5 % and 20 % of it, 7 x 7 patches; CPU time of all threads
// (MeasureProcessCPUTime). Ours on 1 and 2 threads (xphoto's fills run on one). And a clone-brush
// stroke (clone.h) over a 256 x 256 region with its context.
#include <benchmark/benchmark.h>
#include <gdal_priv.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <opencv2/xphoto/inpainting.hpp>
#include <stdexcept>
#include <string>

#include "clone.h"
#include "inpaint.h"
#include "patchmatch.h"

namespace maquette::synthesis::bench {
namespace {

constexpr int kSide = 1000;

const cv::Mat& landsat() {
  static const cv::Mat rgb = [] {
    const std::string path = MAQUETTE_SHARED_DIR "/data/zion/landsat_rgb_b4b3b2_8bit.tif";
    GDALAllRegister();
    std::unique_ptr<GDALDataset> ds(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER));
    cv::Mat m(kSide, kSide, CV_8UC3);
    int bands[] = {1, 2, 3};
    if (!ds || ds->RasterIO(GF_Read, 64, 214, kSide, kSide, m.data, kSide, kSide, GDT_Byte, 3,
                            bands, 3, kSide * 3, 1, nullptr) != CE_None) {
      throw std::runtime_error("cannot read " + path);
    }
    return m;
  }();
  return rgb;
}

// Non-zero in the centred square of `percent` % of the window.
std::vector<uint8_t> hole(int percent) {
  const int side = int(std::lround(std::sqrt(percent / 100.0) * kSide)), x0 = (kSide - side) / 2;
  std::vector<uint8_t> mask(size_t(kSide) * kSide, 0);
  for (int y = x0; y < x0 + side; ++y) {
    for (int x = x0; x < x0 + side; ++x) mask[size_t(y) * kSide + x] = 1;
  }
  return mask;
}

void BM_Ours(benchmark::State& state) {
  const auto mask = hole(int(state.range(0)));
  PatchImage image(kSide, kSide, 3);
  for (size_t i = 0; i < image.values.size(); ++i) image.values[i] = landsat().data[i];
  for (auto _ : state) {
    tbb::task_arena(int(state.range(1))).execute([&] {
      benchmark::DoNotOptimize(inpaint(image, mask, InpaintParams{}, PatchMatch()));
    });
  }
}
BENCHMARK(BM_Ours)
    ->ArgNames({"hole_percent", "threads"})
    ->Args({5, 1})
    ->Args({5, 2})
    ->Args({20, 1})
    ->Args({20, 2})
    ->MeasureProcessCPUTime()
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

void BM_Xphoto(benchmark::State& state) {
  const auto mask = hole(int(state.range(0)));
  cv::Mat known(kSide, kSide, CV_8U), out;
  for (size_t i = 0; i < mask.size(); ++i) known.data[i] = mask[i] != 0 ? 0 : 255;
  cv::Mat damaged = landsat().clone();
  damaged.setTo(cv::Scalar::all(0), known == 0);
  for (auto _ : state) cv::xphoto::inpaint(damaged, known, out, int(state.range(1)));
}
BENCHMARK(BM_Xphoto)
    ->ArgNames({"hole_percent", "algorithm"})  // 0: shift-map, 2: FSR fast
    ->Args({5, cv::xphoto::INPAINT_SHIFTMAP})
    ->Args({20, cv::xphoto::INPAINT_SHIFTMAP})
    ->Args({5, cv::xphoto::INPAINT_FSR_FAST})
    ->Args({20, cv::xphoto::INPAINT_FSR_FAST})
    ->MeasureProcessCPUTime()
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

// A clone-brush stroke: a 256 x 256 region of the window's 512 x 512 top-left quarter (its
// context) copied 200 pixels to the right, its band resynthesized; on 2 threads.
void BM_CloneStroke(benchmark::State& state) {
  constexpr int kContext = 512, kRegion = 256;
  PatchImage image(kContext, kContext, 3);
  for (int y = 0; y < kContext; ++y) {
    for (int x = 0; x < kContext; ++x) {
      for (int c = 0; c < 3; ++c) image.pixel(x, y)[c] = landsat().at<cv::Vec3b>(y, x)[c];
    }
  }
  std::vector<uint8_t> source(size_t(kContext) * kContext, 0);
  for (int y = 128; y < 128 + kRegion; ++y) {
    for (int x = 20; x < 20 + kRegion; ++x) source[size_t(y) * kContext + x] = 1;
  }
  CloneParams params;
  params.offset_x = 200;
  for (auto _ : state) {
    tbb::task_arena(2).execute(
        [&] { benchmark::DoNotOptimize(clone(image, source, params, PatchMatch())); });
  }
}
BENCHMARK(BM_CloneStroke)->MeasureProcessCPUTime()->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace
}  // namespace maquette::synthesis::bench

BENCHMARK_MAIN();
