#include "spread_regions.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include "light_guide.h"

namespace maquette::synthesis {

std::vector<uint8_t> region_quantiles(const ExemplarLevel& level) {
  const int side = 1 << kSpreadRegionShift, w = level.width, h = level.height;
  const size_t n = size_t(w) * size_t(h);
  // Each allowed pixel's value: the mean luma of its region's allowed pixels of its label.
  std::vector<float> region_mean(n, 0.0f);
  std::array<double, 256> sum{};
  std::array<int, 256> count{};
  for (int y0 = 0; y0 < h; y0 += side)
    for (int x0 = 0; x0 < w; x0 += side) {
      const int y1 = std::min(h, y0 + side), x1 = std::min(w, x0 + side);
      const auto each_allowed = [&](auto&& f) {
        for (int y = y0; y < y1; ++y)
          for (int x = x0; x < x1; ++x)
            if (const size_t i = size_t(level.index(x, y)); !level.excluded[i]) f(i);
      };
      each_allowed([&](size_t i) {
        const float* c = &level.rgb[3 * i];
        sum[level.labels[i]] += 0.299 * c[0] + 0.587 * c[1] + 0.114 * c[2];
        ++count[level.labels[i]];
      });
      each_allowed(
          [&](size_t i) { region_mean[i] = float(sum[level.labels[i]] / count[level.labels[i]]); });
      each_allowed([&](size_t i) { sum[level.labels[i]] = 0, count[level.labels[i]] = 0; });
    }
  std::vector<uint8_t> allowed(n);
  for (size_t i = 0; i < n; ++i) allowed[i] = !level.excluded[i];
  const std::vector<float> quantile = class_quantiles(region_mean, level.labels, allowed);
  std::vector<uint8_t> out(n, 128);
  for (size_t i = 0; i < n; ++i)
    if (allowed[i]) out[i] = uint8_t(std::lround(255.0 * double(quantile[i])));
  return out;
}

}  // namespace maquette::synthesis
