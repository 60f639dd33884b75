#include "window_counts.h"

#include <cstddef>

namespace maquette::texture {

std::vector<uint32_t> window_counts(const std::vector<uint8_t>& marked, int n, int radius) {
  const size_t side = size_t(n + 2 * radius), w = side + 1, d = size_t(2 * radius + 1);
  std::vector<uint32_t> sums(w * w, 0);
  for (size_t r = 0; r < side; ++r)
    for (size_t c = 0; c < side; ++c)
      sums[(r + 1) * w + c + 1] = uint32_t(marked[r * side + c] != 0) + sums[r * w + c + 1] +
                                  sums[(r + 1) * w + c] - sums[r * w + c];
  std::vector<uint32_t> out(size_t(n) * size_t(n));
  for (size_t r = 0; r < size_t(n); ++r)
    for (size_t c = 0; c < size_t(n); ++c)
      out[r * size_t(n) + c] =
          sums[(r + d) * w + c + d] - sums[r * w + c + d] - sums[(r + d) * w + c] + sums[r * w + c];
  return out;
}

}  // namespace maquette::texture
