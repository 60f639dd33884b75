#include "vote.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace maquette::synthesis {
namespace {

size_t offset(const PixelRect& r, int64_t col, int64_t row) {
  return size_t(row - r.row0) * size_t(r.width) + size_t(col - r.col0);
}

}  // namespace

bool across_depth_break(float a, float b, double ratio) {
  if (std::isnan(a) || std::isnan(b)) return false;
  if (std::isinf(a) || std::isinf(b)) return std::isinf(a) != std::isinf(b);
  return std::max(a, b) > ratio * std::min(a, b);
}

bool depth_break_within(const std::vector<float>& depth, const PixelRect& rect, int64_t col,
                        int64_t row, int radius, double ratio) {
  if (depth.empty()) return false;
  const float here = depth[offset(rect, col, row)];
  for (int dy = -radius; dy <= radius; ++dy)
    for (int dx = -radius; dx <= radius; ++dx)
      if (across_depth_break(here, depth[offset(rect, col + dx, row + dy)], ratio)) return true;
  return false;
}

std::vector<int32_t> vote(const ExemplarLevel& e, const VoteInputs& in, int radius,
                          const PixelRect& out) {
  std::vector<int32_t> result(size_t(out.width) * size_t(out.height));
  std::vector<int32_t> proposals;
  ExcessPower power(in.balance);
  for (int64_t row = out.row0; row < out.row0 + out.height; ++row)
    for (int64_t col = out.col0; col < out.col0 + out.width; ++col) {
      const size_t g = offset(in.guide_rect, col, row);
      int32_t& winner = result[offset(out, col, row)];
      winner = in.state[offset(in.state_rect, col, row)];
      if (depth_break_within(in.depth, in.guide_rect, col, row, radius, in.depth_break)) continue;
      const uint8_t label = in.labels[g];
      proposals.clear();
      std::array<double, 3> mean{};
      for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx) {
          const int32_t s = in.state[offset(in.state_rect, col + dx, row + dy)];
          const int x = s % e.width - dx, y = s / e.width - dy;
          if (x < 0 || y < 0 || x >= e.width || y >= e.height) continue;
          const int32_t c = e.index(x, y);
          if (e.excluded[size_t(c)] || (label != kUnknownLabel && e.labels[size_t(c)] != label))
            continue;
          proposals.push_back(c);
          for (size_t k = 0; k < 3; ++k) mean[k] += e.rgb[3 * size_t(c) + k];
        }
      double least = std::numeric_limits<double>::infinity();
      for (size_t i = 0; i < proposals.size(); ++i) {
        const int32_t c = proposals[i];
        // A coherent copy proposes one source many times: a repeat's d is the first's, and a
        // tie goes to the first.
        if (i > 0 && c == proposals[i - 1]) continue;
        double d = 0;
        for (size_t k = 0; k < 3; ++k)
          d += std::pow(double(e.rgb[3 * size_t(c) + k]) - mean[k] / double(proposals.size()), 2);
        if (in.balance > 0 && !e.colour_excess.empty())
          d = (d + kBalanceFloor) * power(e.colour_excess[size_t(c)]);
        if (d < least) least = d, winner = c;
      }
    }
  return result;
}

}  // namespace maquette::synthesis
