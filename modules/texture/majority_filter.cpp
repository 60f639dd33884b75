#include "majority_filter.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "window_counts.h"

namespace maquette::texture {

std::vector<int> majority_filter(const std::vector<int>& cls, int n, int radius) {
  const size_t side = size_t(n + 2 * radius);
  std::vector<int> ids;
  for (const int k : cls)
    if (k >= 0 && std::find(ids.begin(), ids.end(), k) == ids.end()) ids.push_back(k);
  std::sort(ids.begin(), ids.end());
  std::vector<std::vector<uint32_t>> counts;  // per class id, per tile pixel
  std::vector<uint8_t> marked(cls.size());
  for (const int id : ids) {
    for (size_t i = 0; i < cls.size(); ++i) marked[i] = cls[i] == id;
    counts.push_back(window_counts(marked, n, radius));
  }
  std::vector<int> out(size_t(n) * size_t(n), -1);
  for (size_t r = 0; r < size_t(n); ++r)
    for (size_t c = 0; c < size_t(n); ++c) {
      const int own = cls[(r + size_t(radius)) * side + c + size_t(radius)];
      if (own < 0) continue;
      const size_t p = r * size_t(n) + c;
      const size_t self = size_t(std::find(ids.begin(), ids.end(), own) - ids.begin());
      size_t best = self;  // replaced only by a strictly larger count: the lowest such id
      for (size_t i = 0; i < ids.size(); ++i)
        if (counts[i][p] > counts[best][p]) best = i;
      out[p] = ids[best];
    }
  return out;
}

}  // namespace maquette::texture
