// Surface-type clusters of a colour histogram for texture.cluster: k-means or a Gaussian mixture
// (seeded from k-means), with k given or chosen automatically (deterministically) up to k_max:
// the largest mean silhouette for k-means (k >= 2), the smallest BIC for the mixture (k >= 1).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "gmm.h"

namespace maquette::texture {

enum class ClusterMethod { KMeans, Gmm };
ClusterMethod parse_cluster_method(const std::string& name);  // "kmeans" or "gmm"

struct ClusterRequest {
  ClusterMethod method = ClusterMethod::KMeans;
  ColourSpace space = ColourSpace::Hs;
  int k = 0;  // 0: choose
  int k_max = 8;
};

struct ColourClusters {
  std::vector<Point> centres;      // in decreasing pixel count (the ids)
  std::vector<uint64_t> pixels;    // pixels of each (bins given to their nearest centre or
                                   // most likely component)
  std::optional<Mixture> mixture;  // for "gmm", components in the order of the centres
  std::vector<int> tried_k;        // when k was chosen: each k tried and its criterion value
  std::vector<double> criterion;
};

// Throws maquette::Error when the histogram is empty.
ColourClusters find_clusters(const std::vector<uint64_t>& histogram, const ClusterRequest& request);

}  // namespace maquette::texture
