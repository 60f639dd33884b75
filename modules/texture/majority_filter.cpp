#include "majority_filter.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>

namespace maquette::texture {

std::vector<int> majority_filter(const std::vector<int>& cls, int n, int radius) {
  const size_t side = size_t(n + 2 * radius), w = side + 1;
  std::vector<int> ids;
  for (const int k : cls)
    if (k >= 0 && std::find(ids.begin(), ids.end(), k) == ids.end()) ids.push_back(k);
  std::sort(ids.begin(), ids.end());
  std::vector<std::vector<uint32_t>> sums(ids.size(), std::vector<uint32_t>(w * w, 0));
  for (size_t i = 0; i < ids.size(); ++i)
    for (size_t r = 0; r < side; ++r)
      for (size_t c = 0; c < side; ++c)
        sums[i][(r + 1) * w + c + 1] = uint32_t(cls[r * side + c] == ids[i]) +
                                       sums[i][r * w + c + 1] + sums[i][(r + 1) * w + c] -
                                       sums[i][r * w + c];
  std::vector<int> out(size_t(n) * size_t(n), -1);
  const size_t d = size_t(2 * radius + 1);
  for (size_t r = 0; r < size_t(n); ++r)
    for (size_t c = 0; c < size_t(n); ++c) {
      const int own = cls[(r + size_t(radius)) * side + c + size_t(radius)];
      if (own < 0) continue;
      const auto count = [&](size_t i) {
        const std::vector<uint32_t>& s = sums[i];
        return s[(r + d) * w + c + d] - s[r * w + c + d] - s[(r + d) * w + c] + s[r * w + c];
      };
      const size_t self = size_t(std::find(ids.begin(), ids.end(), own) - ids.begin());
      size_t best = self;  // replaced only by a strictly larger count: the lowest such id
      for (size_t i = 0; i < ids.size(); ++i)
        if (count(i) > count(best)) best = i;
      out[r * size_t(n) + c] = ids[best];
    }
  return out;
}

}  // namespace maquette::texture
