#include "image/stretch.h"

#include <algorithm>
#include <cmath>

#include "core/round_half_away.h"

namespace maquette {

StretchRange quantile_range(std::vector<float>& v, double q0, double q1) {
  std::erase_if(v, [](float x) { return !std::isfinite(x); });
  if (v.empty()) return {0.0, 1.0};
  auto nth = [&](double q) {
    auto it = v.begin() + std::ptrdiff_t(q * double(v.size() - 1));
    std::nth_element(v.begin(), it, v.end());
    return double(*it);
  };
  const double lo = nth(q0), hi = nth(q1);
  return {lo, hi > lo ? hi : lo + 1.0};
}

uint8_t stretch_byte(double value, const StretchRange& range) {
  const double t = (value - range.first) / (range.second - range.first);
  return uint8_t(round_half_away(255.0 * std::clamp(t, 0.0, 1.0)));
}

}  // namespace maquette
