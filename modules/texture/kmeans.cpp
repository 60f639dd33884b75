#include "kmeans.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace maquette::texture {

int hs_bin(const Hsv& x) {
  const int h = std::clamp(int(x.h / 360 * kHueBins), 0, kHueBins - 1);
  const int s = std::clamp(int(x.s * kSatBins), 0, kSatBins - 1);
  return h * kSatBins + s;
}

std::vector<Cluster> kmeans(const std::vector<uint64_t>& histogram, int k) {
  struct Point {
    std::array<double, 2> p;
    double w;
  };
  std::vector<Point> pts;
  for (int i = 0; i < kHueBins * kSatBins; ++i)
    if (histogram[size_t(i)] > 0)
      pts.push_back(
          {wheel((i / kSatBins + 0.5) * 360.0 / kHueBins, (i % kSatBins + 0.5) / kSatBins),
           double(histogram[size_t(i)])});
  const auto d2 = [](const std::array<double, 2>& a, const std::array<double, 2>& b) {
    return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]);
  };
  const auto nearest = [&](const std::vector<std::array<double, 2>>& cs, const Point& x) {
    size_t best = 0;
    for (size_t c = 1; c < cs.size(); ++c)
      if (d2(x.p, cs[c]) < d2(x.p, cs[best])) best = c;
    return best;
  };
  std::vector<std::array<double, 2>> centres;
  const size_t kk = std::min(size_t(std::max(k, 1)), pts.size());
  while (centres.size() < kk) {
    size_t pick = 0;
    double best = -1;
    for (size_t i = 0; i < pts.size(); ++i) {
      const double score =
          centres.empty() ? pts[i].w : pts[i].w * d2(pts[i].p, centres[nearest(centres, pts[i])]);
      if (score > best) best = score, pick = i;  // first of equals: deterministic
    }
    centres.push_back(pts[pick].p);
  }
  std::vector<size_t> assign(pts.size(), kk);
  for (int iter = 0; iter < 100; ++iter) {
    bool changed = false;
    for (size_t i = 0; i < pts.size(); ++i) {
      const size_t c = nearest(centres, pts[i]);
      changed = changed || c != assign[i];
      assign[i] = c;
    }
    if (!changed) break;
    std::vector<std::array<double, 3>> acc(kk, {0, 0, 0});
    for (size_t i = 0; i < pts.size(); ++i)
      acc[assign[i]] = {acc[assign[i]][0] + pts[i].w * pts[i].p[0],
                        acc[assign[i]][1] + pts[i].w * pts[i].p[1], acc[assign[i]][2] + pts[i].w};
    for (size_t c = 0; c < kk; ++c)
      if (acc[c][2] > 0) centres[c] = {acc[c][0] / acc[c][2], acc[c][1] / acc[c][2]};
  }
  std::vector<Cluster> out(kk);
  for (size_t c = 0; c < kk; ++c) {
    const double hue = std::atan2(centres[c][1], centres[c][0]) * 180 / M_PI;
    out[c].centre = {0, hue < 0 ? hue + 360 : hue, std::hypot(centres[c][0], centres[c][1])};
  }
  for (size_t i = 0; i < pts.size(); ++i) out[assign[i]].pixels += uint64_t(pts[i].w);
  std::stable_sort(out.begin(), out.end(), [](auto& a, auto& b) { return a.pixels > b.pixels; });
  for (size_t c = 0; c < kk; ++c) out[c].centre.id = int(c);
  return out;
}

}  // namespace maquette::texture
