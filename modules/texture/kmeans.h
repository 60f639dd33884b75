// Automatic classes in hue-saturation space: a hue-saturation histogram of the image and
// weighted k-means on the colour wheel over its bins (deterministic: seeded with the heaviest
// bin, then each next seed the bin of largest weight x squared distance to the seeds so far).
#pragma once

#include <cstdint>
#include <vector>

#include "hs_classes.h"

namespace maquette::texture {

inline constexpr int kHueBins = 72, kSatBins = 20;  // 5 degrees x 0.05

int hs_bin(const Hsv& x);  // index into a kHueBins * kSatBins histogram

struct Cluster {
  Centre centre;
  uint64_t pixels = 0;
};

// k clusters (fewer when fewer bins are occupied), ids 0.. in decreasing pixel count.
std::vector<Cluster> kmeans(const std::vector<uint64_t>& histogram, int k);

}  // namespace maquette::texture
