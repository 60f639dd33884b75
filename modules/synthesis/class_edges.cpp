#include "class_edges.h"

#include <algorithm>
#include <bitset>
#include <cstddef>

namespace maquette::synthesis {
namespace {

// out[x] = 1 where a non-zero in[] lies within `reach` of x along the line (a row, or with
// `stride` the width a column), else 0.
void dilate_line(const uint8_t* in, uint8_t* out, int n, ptrdiff_t stride, int reach) {
  int last = -reach - 1;  // the last set pixel at or before x + reach
  for (int x = 0, ahead = 0; x < n; ++x) {
    for (; ahead < n && ahead <= x + reach; ++ahead)
      if (in[ahead * stride]) last = ahead;
    out[x * stride] = last >= x - reach ? 1 : 0;
  }
}

}  // namespace

std::vector<uint64_t> class_edge_places(const ExemplarLevel& level) {
  const int w = level.width, h = level.height;
  const size_t n = size_t(w) * size_t(h);
  std::bitset<256> present;
  for (const int32_t i : level.allowed) present.set(level.labels[size_t(i)]);
  present.reset(kUnknownLabel);
  std::vector<uint64_t> places;
  std::vector<uint8_t> of_b(n), rows(n), near_b(n);
  for (int b = 0; b < kUnknownLabel; ++b) {
    if (!present[size_t(b)]) continue;
    std::fill(of_b.begin(), of_b.end(), uint8_t{0});
    for (const int32_t i : level.allowed) of_b[size_t(i)] = level.labels[size_t(i)] == b;
    for (int y = 0; y < h; ++y)
      dilate_line(of_b.data() + size_t(y) * size_t(w), rows.data() + size_t(y) * size_t(w), w, 1,
                  kClassEdgeReach);
    for (int x = 0; x < w; ++x)
      dilate_line(rows.data() + x, near_b.data() + x, h, w, kClassEdgeReach);
    for (const int32_t i : level.allowed) {
      const uint8_t a = level.labels[size_t(i)];
      if (a != b && a != kUnknownLabel && near_b[size_t(i)])
        places.push_back(class_edge_entry(a, uint8_t(b), i));
    }
  }
  std::sort(places.begin(), places.end());
  return places;
}

std::span<const uint64_t> class_edge_run(const std::vector<uint64_t>& places, uint8_t a,
                                         uint8_t b) {
  const auto first = std::lower_bound(places.begin(), places.end(), class_edge_entry(a, b, 0));
  const auto last =
      std::lower_bound(first, places.end(), class_edge_entry(a, b, 0) + (uint64_t(1) << 32));
  return {first, last};
}

}  // namespace maquette::synthesis
