#include "seam_cut.h"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <string>

#include "core/error.h"

namespace maquette::synthesis {

std::vector<int> seam_cut(const std::vector<float>& error, int64_t s_first, int length, int depth,
                          int pin_period) {
  if (depth < 3 || pin_period < 1 || length < 0 || length % pin_period != 0 ||
      s_first % pin_period != 0 || error.size() != size_t(length) * size_t(depth))
    throw Error("seam cut: a band of " + std::to_string(length) + " x " + std::to_string(depth) +
                " from " + std::to_string(s_first) + " with pins every " +
                std::to_string(pin_period) + " and " + std::to_string(error.size()) + " errors");
  const int pin = depth / 2;
  const auto pair = [&](int i, int t) {
    return double(error[size_t(t - 1) * size_t(length) + size_t(i)]) +
           double(error[size_t(t) * size_t(length) + size_t(i)]);
  };
  constexpr double kNone = std::numeric_limits<double>::infinity();
  std::vector<int> cut(size_t(length), pin);
  const size_t rows = size_t(depth);
  std::vector<double> cost(rows), next(rows);
  std::vector<int8_t> step(size_t(pin_period) * size_t(depth));  // to the predecessor
  for (int i0 = 0; i0 < length; i0 += pin_period) {
    std::fill(cost.begin(), cost.end(), kNone);
    cost[size_t(pin)] = pair(i0, pin);
    for (int i = i0 + 1; i < i0 + pin_period; ++i) {
      next[0] = kNone;
      for (int t = 1; t < depth; ++t) {
        double best = kNone;
        int8_t from = 0;
        for (const int8_t d : {0, -1, 1})
          if (t + d >= 1 && t + d < depth && cost[size_t(t + d)] < best) {
            best = cost[size_t(t + d)];
            from = d;
          }
        next[size_t(t)] = best + pair(i, t);
        step[size_t(i - i0) * size_t(depth) + size_t(t)] = from;
      }
      std::swap(cost, next);
    }
    // The last position meets the next pin within one step.
    int t = pin;
    for (const int u : {pin - 1, pin, pin + 1})
      if (u >= 1 && u < depth && cost[size_t(u)] < cost[size_t(t)]) t = u;
    for (int i = i0 + pin_period - 1; i > i0; --i) {
      cut[size_t(i)] = t;
      t += step[size_t(i - i0) * size_t(depth) + size_t(t)];
    }
  }
  return cut;
}

}  // namespace maquette::synthesis
