#include "voids.h"

#include <algorithm>
#include <cmath>

namespace maquette::terrain {

std::vector<Void> find_voids(const Tile<float>& dem) {
  const int halo = dem.halo(), stride = dem.stride();
  const std::span<const float> data = dem.data();
  std::vector<char> seen(data.size(), 0);
  std::vector<Void> voids;
  std::vector<int> stack;
  for (int row = 0; row < dem.size(); ++row)
    for (int col = 0; col < dem.size(); ++col) {
      const int start = (row + halo) * stride + col + halo;
      if (!std::isnan(data[start]) || seen[start]) continue;
      Void v;
      int col_min = stride, col_max = -1, row_min = stride, row_max = -1;
      seen[start] = 1;
      stack.assign(1, start);
      while (!stack.empty()) {
        const int s = stack.back();
        stack.pop_back();
        v.samples.push_back(s);
        const int c = s % stride, r = s / stride;
        col_min = std::min(col_min, c);
        col_max = std::max(col_max, c);
        row_min = std::min(row_min, r);
        row_max = std::max(row_max, r);
        if (c == 0 || r == 0 || c == stride - 1 || r == stride - 1) v.reaches_edge = true;
        const auto visit = [&](int n) {
          if (!std::isnan(data[n]) || seen[n]) return;
          seen[n] = 1;
          stack.push_back(n);
        };
        if (c > 0) visit(s - 1);
        if (c < stride - 1) visit(s + 1);
        if (r > 0) visit(s - stride);
        if (r < stride - 1) visit(s + stride);
      }
      std::sort(v.samples.begin(), v.samples.end());
      v.extent = std::max(col_max - col_min, row_max - row_min) + 1;
      voids.push_back(std::move(v));
    }
  return voids;
}

}  // namespace maquette::terrain
