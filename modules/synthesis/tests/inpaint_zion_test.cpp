// The completion on real imagery (Landsat 8 over Zion, ../shared/data) with holes of known
// content: 5 % and 20 % of a 128 x 128 window and a bridge-like strip across it. Against the
// original: no seam and little blur on the hole's edge, judged over seeds 0-3 (review C-R-S3: one
// seed's ratio moves by up to 0.15 with the draw alone): each seed's mean gradient there at most
// 1.25 x the original's, and the mean over the seeds at least the 0.8 (measured 1.01 for
// the 5 % hole, 0.83 for the 20 % hole and 0.86 for the strip: the 20 % hole's margin is 0.03,
// less than one seed's spread, 0.76-0.92; with the finest level's last vote a mean instead of a
// mode the means were 0.87, 0.71 and 0.74, and this gate fails).
// Against OpenCV xphoto's shift-map and FSR fills of the same holes: a lower
// bidirectional-similarity energy for every seed (inpaint_measures.h). The same bits on one and
// two threads. A clone-brush stroke on the same window: its band without a seam, against the
// hard-edged copy.
#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <filesystem>
#include <opencv2/xphoto/inpainting.hpp>
#include <string>

#include "../clone.h"
#include "../inpaint.h"
#include "../patchmatch.h"
#include "inpaint_measures.h"
#include "synthetic_images.h"
#include "zion_ingest.h"

namespace maquette::synthesis {
namespace {

const std::string kLandsat = kShared + "/zion/landsat_rgb_b4b3b2_8bit.tif";
constexpr int kSide = 128;
// The seeds each hole is filled with: the gradient gate is on their mean, the fill's sharpness
// rather than one draw's (the worst of them would judge the draw: 0.65 for the 20 % hole).
constexpr uint64_t kSeeds = 4;

// The window of the Landsat RGB at (x0, y0), as GDAL reads it.
cv::Mat landsat_window(int x0, int y0) {
  GDALAllRegister();
  std::unique_ptr<GDALDataset> ds(GDALDataset::Open(kLandsat.c_str(), GDAL_OF_RASTER));
  cv::Mat rgb(kSide, kSide, CV_8UC3);
  int bands[] = {1, 2, 3};
  if (ds == nullptr || ds->RasterIO(GF_Read, x0, y0, kSide, kSide, rgb.data, kSide, kSide, GDT_Byte,
                                    3, bands, 3, kSide * 3, 1, nullptr) != CE_None) {
    throw std::runtime_error("cannot read " + kLandsat);
  }
  return rgb;
}

// The least mean over the seeds of the edge gradient ratio: the issue's.
constexpr double kLeastEdgeGradient = 0.8;

struct Hole {
  std::string name;
  std::vector<uint8_t> mask;
};

std::vector<Hole> holes() {
  const auto centred_square = [](double fraction) {
    const int side = int(std::lround(std::sqrt(fraction * kSide * kSide)));
    std::vector<uint8_t> mask(kSide * kSide, 0);
    const int x0 = (kSide - side) / 2;
    for (int y = x0; y < x0 + side; ++y) {
      for (int x = x0; x < x0 + side; ++x) mask[size_t(y) * kSide + x] = 1;
    }
    return mask;
  };
  // A bridge's footprint: a strip 8 pixels wide crossing the window at about 30 degrees.
  std::vector<uint8_t> strip(kSide * kSide, 0);
  for (int y = 0; y < kSide; ++y) {
    for (int x = 0; x < kSide; ++x) {
      strip[size_t(y) * kSide + x] = std::abs((y - 64) - 0.58 * (x - 64)) * 0.866 < 4;
    }
  }
  return {{"5 %", centred_square(0.05)}, {"20 %", centred_square(0.20)}, {"strip", strip}};
}

cv::Mat ours(const cv::Mat& rgb, const std::vector<uint8_t>& hole, uint64_t seed = 0) {
  InpaintParams params;
  params.seed = seed;
  return test::to_mat(inpaint(test::to_patch_image(rgb), hole, params, PatchMatch()));
}

cv::Mat xphoto(const cv::Mat& rgb, const std::vector<uint8_t>& hole, int algorithm) {
  cv::Mat known(rgb.rows, rgb.cols, CV_8U), out;
  for (int i = 0; i < rgb.rows * rgb.cols; ++i) known.data[i] = hole[size_t(i)] != 0 ? 0 : 255;
  cv::Mat damaged = rgb.clone();
  damaged.setTo(cv::Scalar::all(0), known == 0);
  cv::xphoto::inpaint(damaged, known, out, algorithm);
  return out;
}

TEST(InpaintZion, NoSeamAndLowerEnergyThanXphotoOnHolesOfKnownContent) {
  if (!std::filesystem::exists(kLandsat)) GTEST_SKIP() << "../shared/data is absent";
  const cv::Mat rgb = landsat_window(560, 700);
  const int band = InpaintParams{}.band;
  for (const Hole& hole : holes()) {
    const auto shiftmap = test::bidirectional_energy(
        rgb, xphoto(rgb, hole.mask, cv::xphoto::INPAINT_SHIFTMAP), hole.mask, band);
    const auto fsr = test::bidirectional_energy(
        rgb, xphoto(rgb, hole.mask, cv::xphoto::INPAINT_FSR_FAST), hole.mask, band);
    std::cout << hole.name << ": energy (coherence + completeness) shift-map " << shiftmap.coherence
              << " + " << shiftmap.completeness << ", FSR fast " << fsr.coherence << " + "
              << fsr.completeness << "\n";
    double mean_ratio = 0;
    for (uint64_t seed = 0; seed < kSeeds; ++seed) {
      const cv::Mat filled = ours(rgb, hole.mask, seed);
      const double ratio =
          test::edge_gradient(filled, hole.mask) / test::edge_gradient(rgb, hole.mask);
      mean_ratio += ratio / kSeeds;
      const auto energy = test::bidirectional_energy(rgb, filled, hole.mask, band);
      std::cout << "  seed " << seed << ": edge gradient ratio " << ratio << "; energy ours "
                << energy.coherence << " + " << energy.completeness << "\n";
      EXPECT_LE(ratio, 1.25) << hole.name << ", seed " << seed;
      EXPECT_LT(energy.total(), shiftmap.total()) << hole.name << ", seed " << seed;
      EXPECT_LT(energy.total(), fsr.total()) << hole.name << ", seed " << seed;
    }
    std::cout << "  mean edge gradient ratio " << mean_ratio << "\n";
    EXPECT_GE(mean_ratio, kLeastEdgeGradient) << hole.name;
  }
}

// A clone-brush stroke on the same window: a 44 x 44 square copied 68 pixels right and down. The
// band across the destination's edge (3 pixels each side) against the hard-edged copy (band 0):
// no seam and little blur there (the mean gradient on the destination's edge within 0.8-1.25 x
// the original's there, the mean over seeds 0-3; the hard copy's seam is above it), and a lower
// bidirectional-similarity energy of the band's patches than the hard copy's, for every seed
// (both measured against the hard copy, the image the band is resynthesized in). The clone's
// short completion (clone.h: 2 EM iterations of 1 search pass, for the stroke's speed) against
// the inpainting's 8 x 2 (seed 0 only: its seeds 0-3 spread by 2 %, and it is the test's
// costliest fill): an energy at most kShortCompletionEnergy times its for every seed (measured
// 1.09-1.12; the margin, 3 %, is about the short completion's spread over the seeds; the hard
// copy: 1.31).
constexpr double kShortCompletionEnergy = 1.15;

TEST(CloneZion, TheBandAcrossTheCopysEdgeShowsNoSeamAndBeatsTheHardCopy) {
  if (!std::filesystem::exists(kLandsat)) GTEST_SKIP() << "../shared/data is absent";
  const cv::Mat rgb = landsat_window(560, 700);
  constexpr int kSource = 8, kSquare = 44, kOffset = 68;
  const auto destination =
      test::square_mask(kSide, kSide, kSource + kOffset, kSource + kOffset, kSquare);
  CloneParams params;
  params.offset_x = params.offset_y = kOffset;
  const int band = params.fill.band;
  // The band: pixels within `band` (chessboard) of the destination's edge, on either side.
  std::vector<uint8_t> ring(destination.size(), 0);
  for (int y = 0; y < kSide; ++y) {
    for (int x = 0; x < kSide; ++x) {
      const int lo = kSource + kOffset, hi = lo + kSquare - 1;
      const int out = std::max({lo - x, x - hi, lo - y, y - hi});  // > 0 outside the square
      const int in = std::min({x - lo, hi - x, y - lo, hi - y});   // >= 0 inside
      ring[size_t(y) * kSide + x] = out > 0 ? out <= band : in < band;
    }
  }
  const auto source = test::square_mask(kSide, kSide, kSource, kSource, kSquare);
  CloneParams hard_params = params;
  hard_params.fill.band = 0;
  const cv::Mat hard =
      test::to_mat(clone(test::to_patch_image(rgb), source, hard_params, PatchMatch()));
  const double original_gradient = test::edge_gradient(rgb, destination);
  const double hard_ratio = test::edge_gradient(hard, destination) / original_gradient;
  const auto hard_energy = test::bidirectional_energy(hard, hard, ring, 0);
  std::cout << "hard copy: edge gradient ratio " << hard_ratio << ", energy "
            << hard_energy.coherence << " + " << hard_energy.completeness << "\n";
  CloneParams full_params = params;
  full_params.fill.em_iterations = InpaintParams{}.em_iterations;
  full_params.fill.search_iterations = InpaintParams{}.search_iterations;
  const auto full_energy = test::bidirectional_energy(
      hard, test::to_mat(clone(test::to_patch_image(rgb), source, full_params, PatchMatch())), ring,
      0);
  std::cout << "the 8 x 2 completion: energy " << full_energy.coherence << " + "
            << full_energy.completeness << "\n";
  double mean_ratio = 0;
  for (uint64_t seed = 0; seed < kSeeds; ++seed) {
    params.fill.seed = seed;
    const cv::Mat cloned =
        test::to_mat(clone(test::to_patch_image(rgb), source, params, PatchMatch()));
    const double ratio = test::edge_gradient(cloned, destination) / original_gradient;
    mean_ratio += ratio / kSeeds;
    const auto energy = test::bidirectional_energy(hard, cloned, ring, 0);
    std::cout << "  seed " << seed << ": edge gradient ratio " << ratio << "; energy "
              << energy.coherence << " + " << energy.completeness << ", "
              << energy.total() / full_energy.total() << " x the 8 x 2 completion's\n";
    EXPECT_LE(ratio, 1.25) << "seed " << seed;
    EXPECT_LT(energy.total(), hard_energy.total()) << "seed " << seed;
    EXPECT_LE(energy.total(), kShortCompletionEnergy * full_energy.total()) << "seed " << seed;
  }
  std::cout << "  mean edge gradient ratio " << mean_ratio << "\n";
  EXPECT_GT(hard_ratio, 1.25);  // the seam the band removes
  EXPECT_GE(mean_ratio, kLeastEdgeGradient);
}

TEST(InpaintZion, SameBitsOnOneAndTwoThreads) {
  if (!std::filesystem::exists(kLandsat)) GTEST_SKIP() << "../shared/data is absent";
  const cv::Mat rgb = landsat_window(560, 700);
  const auto hole = holes()[1].mask;
  const auto run = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    return inpaint(test::to_patch_image(rgb), hole, InpaintParams{}, PatchMatch()).values;
  };
  EXPECT_EQ(run(1), run(2));
}

}  // namespace
}  // namespace maquette::synthesis
