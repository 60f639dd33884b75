// The exemplar analysed for the synthesis (Lefebvre & Hoppe 2005, section 3): a Gaussian pyramid,
// at each level every pixel's 3x3 colour neighbourhood reduced by PCA to kFeatureDims numbers,
// and its k most similar neighbourhoods elsewhere in the exemplar (k-coherence candidates).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "combined_exemplar.h"
#include "exemplar.h"

namespace maquette::synthesis {

inline constexpr int kPatchRadius = 1;  // neighbourhoods of 3 x 3 pixels
inline constexpr int kPatchSide = 2 * kPatchRadius + 1;
inline constexpr int kPatchValues = kPatchSide * kPatchSide * 3;  // RGB
inline constexpr int kFeatureDims = 8;                            // PCA-reduced neighbourhood

// The projection of raw neighbourhoods (kPatchValues colours 0..1, rows of the patch top to
// bottom, RGB interleaved) onto their first kFeatureDims principal axes.
struct PatchBasis {
  std::array<float, kPatchValues> mean{};
  std::array<std::array<float, kPatchValues>, kFeatureDims> axes{};

  std::array<float, kFeatureDims> project(const std::array<float, kPatchValues>& patch) const;
};

struct ExemplarLevel {
  int width = 0, height = 0;
  std::vector<float> rgb;         // 3 per pixel, 0..1
  std::vector<uint8_t> labels;    // painting class
  std::vector<float> altitude;    // [0, 1], or empty
  std::vector<float> distance;    // [0, 1] (1: far), or empty
  std::vector<float> light;       // [0, 1] (1: the lightest of its class), or empty
  std::vector<uint8_t> excluded;  // 1: never a candidate
  PatchBasis basis;
  std::vector<float> features;  // kFeatureDims per pixel
  // k per pixel: the allowed pixels whose neighbourhoods are nearest to this pixel's, farther
  // than one patch away from it (-1 when fewer exist); excluded pixels have none.
  std::vector<int32_t> similar;
  std::vector<int32_t> allowed;                    // pixels not excluded, ascending
  std::array<std::vector<int32_t>, 256> by_label;  // allowed pixels of each label, ascending
  // How much the synthesis over-uses each pixel (exemplar_usage.h), or empty: not measured.
  std::vector<float> usage;
  // How much more often the synthesis shows each pixel's colour than the exemplar has it, per
  // label (exemplar_usage.h), or empty: not measured.
  std::vector<float> colour_excess;
  // The finest level's places beside another class (class_edges.h); empty at coarser levels.
  std::vector<uint64_t> class_edges;
  // Each pixel's region's lightness within its class, in 255ths (region_quantiles,
  // spread_regions.h), or empty: every region typical.
  std::vector<uint8_t> region_quantile;

  int32_t index(int x, int y) const { return y * width + x; }
  // The neighbourhood of (x, y) with coordinates clamped into the level.
  std::array<float, kPatchValues> patch(int x, int y) const;
};

struct ExemplarPyramid {
  int k = 0;
  std::vector<ExemplarLevel> levels;  // finest first
};

// `levels` >= 1 levels, each half the size of the previous one (rounded up): colours,
// altitude, distance and light filtered by the binomial kernel [1 4 6 4 1] / 16 (borders clamped)
// and decimated; labels decimated; a pixel excluded when any pixel of its 2 x 2 block below is. k
// >= 1. `paintings`: where the paintings lie in a combined exemplar (combined_exemplar.h), each x0
// a multiple of 1 << (levels - 1); empty: the whole exemplar is one painting. Each level's PCA
// basis is fitted over the paintings' pixels alone (at level l a painting's columns from
// x0 >> l, its width and height divided by 2^l rounded up, from row 0), excluded ones included,
// the gap's filler not. Deterministic for any threads (the k nearest searches run in parallel,
// each query on its own, ties broken by index). The finest level's class_edges are indexed
// (class_edges.h), each level's region_quantile measured (spread_regions.h). Throws maquette::Error
// when a level has no allowed pixel.
ExemplarPyramid analyse_exemplar(const Exemplar& exemplar, int levels, int k,
                                 const std::vector<Placement>& paintings = {});

}  // namespace maquette::synthesis
