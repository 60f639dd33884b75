#include "kmeans.h"

#include <algorithm>
#include <cmath>

namespace maquette::texture {

size_t nearest_centre(const std::vector<Point>& centres, const Point& x) {
  size_t best = 0;
  for (size_t c = 1; c < centres.size(); ++c)
    if (squared_distance(x, centres[c]) < squared_distance(x, centres[best])) best = c;
  return best;
}

Partition kmeans(const std::vector<BinPoint>& bins, int k) {
  Partition out;
  const size_t kk = std::min(size_t(std::max(k, 1)), bins.size());
  while (out.centres.size() < kk) {
    size_t pick = 0;
    double best = -1;
    for (size_t i = 0; i < bins.size(); ++i) {
      const double score =
          out.centres.empty()
              ? bins[i].w
              : bins[i].w * squared_distance(bins[i].x,
                                             out.centres[nearest_centre(out.centres, bins[i].x)]);
      if (score > best) best = score, pick = i;  // first of equals: deterministic
    }
    out.centres.push_back(bins[pick].x);
  }
  out.assign.assign(bins.size(), kk);
  for (int iter = 0; iter < 100; ++iter) {
    bool changed = false;
    for (size_t i = 0; i < bins.size(); ++i) {
      const size_t c = nearest_centre(out.centres, bins[i].x);
      changed = changed || c != out.assign[i];
      out.assign[i] = c;
    }
    if (!changed) break;
    std::vector<Point> sum(kk, Point{0, 0, 0});
    std::vector<double> weight(kk, 0);
    for (size_t i = 0; i < bins.size(); ++i) {
      for (int d = 0; d < 3; ++d) sum[out.assign[i]][size_t(d)] += bins[i].w * bins[i].x[size_t(d)];
      weight[out.assign[i]] += bins[i].w;
    }
    for (size_t c = 0; c < kk; ++c)
      if (weight[c] > 0)
        out.centres[c] = {sum[c][0] / weight[c], sum[c][1] / weight[c], sum[c][2] / weight[c]};
  }
  return out;
}

double silhouette(const std::vector<BinPoint>& bins, const Partition& partition) {
  const size_t k = partition.centres.size(), n = bins.size();
  // to[i * k + c]: summed distance from bin i's centre to the pixels of cluster c.
  std::vector<double> to(n * k, 0), size(k, 0);
  for (size_t i = 0; i < n; ++i) {
    size[partition.assign[i]] += bins[i].w;
    for (size_t j = i + 1; j < n; ++j) {
      const double d = std::sqrt(squared_distance(bins[i].x, bins[j].x));
      to[i * k + partition.assign[j]] += bins[j].w * d;
      to[j * k + partition.assign[i]] += bins[i].w * d;
    }
  }
  double sum = 0, total = 0;
  for (size_t i = 0; i < n; ++i) {
    total += bins[i].w;
    const size_t own = partition.assign[i];
    if (size[own] <= 1) continue;                        // a lone pixel: s = 0
    const double a = to[i * k + own] / (size[own] - 1);  // the bin's other pixels are at 0
    double b = INFINITY;
    for (size_t c = 0; c < k; ++c)
      if (c != own && size[c] > 0) b = std::min(b, to[i * k + c] / size[c]);
    if (std::isfinite(b) && std::max(a, b) > 0) sum += bins[i].w * (b - a) / std::max(a, b);
  }
  return total > 0 ? sum / total : 0;
}

}  // namespace maquette::texture
