// Weighted k-means over the occupied bins of a colour histogram (hs_histogram.h), deterministic:
// seeded with the heaviest bin, then each next seed the bin of largest weight x squared distance
// to the seeds so far (first of equals), Lloyd iterations until no bin changes cluster (at most
// 100). And the silhouette of a partition, the criterion that chooses k for k-means.
#pragma once

#include <cstddef>
#include <vector>

#include "hs_histogram.h"

namespace maquette::texture {

struct Partition {
  std::vector<Point> centres;  // weighted means of their bins
  std::vector<size_t> assign;  // cluster of each bin
};

// min(k, bins) clusters; k >= 1.
Partition kmeans(const std::vector<BinPoint>& bins, int k);

// Index of the centre nearest to x (first of equals).
size_t nearest_centre(const std::vector<Point>& centres, const Point& x);

// Mean silhouette over the pixels, each pixel at its bin centre (exact for the binned data):
// s = (b - a) / max(a, b), a the mean distance to the other pixels of its cluster, b the least
// mean distance to another cluster's pixels; 0 for a pixel alone in its cluster. O(bins^2).
double silhouette(const std::vector<BinPoint>& bins, const Partition& partition);

}  // namespace maquette::texture
