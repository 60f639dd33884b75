#include "colour_clusters.h"

#include <algorithm>
#include <numeric>

#include "core/error.h"

namespace maquette::texture {
namespace {

// One clustering with k given: centres, the cluster of each bin, and the mixture for "gmm".
struct Fit {
  Partition partition;
  std::optional<Mixture> mixture;
};

Fit fit(const std::vector<BinPoint>& bins, const ClusterRequest& request, int k) {
  Fit f{kmeans(bins, k), std::nullopt};
  if (request.method == ClusterMethod::Gmm) {
    f.mixture = fit_gmm(bins, request.space, f.partition);
    f.partition.assign = most_likely_component(bins, *f.mixture);
    for (size_t c = 0; c < f.partition.centres.size(); ++c)
      f.partition.centres[c] = f.mixture->components[c].mean;
  }
  return f;
}

// Chooses k in [k_min, k_max] (as far as there are bins) by the method's criterion; records
// the values tried.
Fit choose_k(const std::vector<BinPoint>& bins, const ClusterRequest& request, double pixels,
             ColourClusters& out) {
  const bool gmm = request.method == ClusterMethod::Gmm;
  const int k_min = gmm ? 1 : 2;
  const int k_max = std::min(request.k_max, int(bins.size()));
  if (k_max < k_min) return fit(bins, request, 1);  // one occupied bin
  std::optional<Fit> best;
  double best_value = 0;
  for (int k = k_min; k <= k_max; ++k) {
    Fit f = fit(bins, request, k);
    const double value = gmm ? -bic(*f.mixture, pixels) : silhouette(bins, f.partition);
    out.tried_k.push_back(k);
    out.criterion.push_back(gmm ? -value : value);
    if (!best || value > best_value) best = std::move(f), best_value = value;  // first of equals
  }
  return std::move(*best);
}

}  // namespace

ClusterMethod parse_cluster_method(const std::string& name) {
  if (name == "kmeans") return ClusterMethod::KMeans;
  if (name == "gmm") return ClusterMethod::Gmm;
  throw Error("unknown clustering method '" + name + "' (expected kmeans or gmm)");
}

ColourClusters find_clusters(const std::vector<uint64_t>& histogram,
                             const ClusterRequest& request) {
  const std::vector<BinPoint> bins = occupied_bins(histogram, request.space);
  if (bins.empty()) throw Error("no pixel in the colour histogram");
  const double pixels = std::accumulate(bins.begin(), bins.end(), 0.0,
                                        [](double s, const BinPoint& b) { return s + b.w; });
  ColourClusters out;
  const Fit f =
      request.k > 0 ? fit(bins, request, request.k) : choose_k(bins, request, pixels, out);
  const size_t k = f.partition.centres.size();
  std::vector<uint64_t> pixels_of(k, 0);
  for (size_t i = 0; i < bins.size(); ++i) pixels_of[f.partition.assign[i]] += uint64_t(bins[i].w);
  std::vector<size_t> order(k);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return pixels_of[a] > pixels_of[b]; });
  if (f.mixture)
    out.mixture = Mixture{f.mixture->dims, {}, f.mixture->log_likelihood, f.mixture->iterations};
  for (size_t c : order) {
    out.centres.push_back(f.partition.centres[c]);
    out.pixels.push_back(pixels_of[c]);
    if (f.mixture) out.mixture->components.push_back(f.mixture->components[c]);
  }
  return out;
}

}  // namespace maquette::texture
