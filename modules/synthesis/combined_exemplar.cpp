#include "combined_exemplar.h"

#include <algorithm>
#include <cstddef>
#include <utility>

#include "synthesis.h"

namespace maquette::synthesis {

Exemplar combine_exemplars(std::vector<Exemplar> parts, std::vector<Placement>& placement) {
  placement.clear();
  constexpr int kAlign = 1 << (kLevels - 1);
  int end = 0, height = 0;
  for (const Exemplar& e : parts) {
    const int x0 = placement.empty() ? 0 : (end + kCombinedGap + kAlign - 1) / kAlign * kAlign;
    placement.push_back({x0, e.width, e.height});
    end = x0 + e.width;
    height = std::max(height, e.height);
  }
  if (parts.size() == 1) return std::move(parts.front());  // one painting: itself, not a copy
  Exemplar c;
  c.width = end;
  c.height = height;
  const size_t n = size_t(c.width) * size_t(c.height);
  c.rgb.resize(3 * n);
  c.labels.assign(n, 0);
  c.excluded.assign(n, 1);
  if (!parts.front().altitude.empty()) c.altitude.resize(n);
  if (!parts.front().distance.empty()) c.distance.resize(n);
  if (!parts.front().light.empty()) c.light.resize(n);
  for (int x = 0; x < c.width; ++x) {
    // The nearest exemplar in columns (ties to the left) and the column clamped into it.
    size_t p = 0;
    for (size_t q = 1; q < parts.size(); ++q) {
      const auto gap = [&](size_t i) {
        const Placement& at = placement[i];
        return x < at.x0 ? at.x0 - x : std::max(0, x - (at.x0 + at.width - 1));
      };
      if (gap(q) < gap(p)) p = q;
    }
    const Exemplar& e = parts[p];
    const Placement& at = placement[p];
    const int ex = std::clamp(x - at.x0, 0, e.width - 1);
    const bool inside = x >= at.x0 && x < at.x0 + e.width;
    for (int y = 0; y < c.height; ++y) {
      const size_t i = size_t(y) * size_t(c.width) + size_t(x);
      const size_t j = size_t(std::min(y, e.height - 1)) * size_t(e.width) + size_t(ex);
      std::copy_n(e.rgb.begin() + std::ptrdiff_t(3 * j), 3, c.rgb.begin() + std::ptrdiff_t(3 * i));
      if (!c.altitude.empty()) c.altitude[i] = e.altitude[j];
      if (!c.distance.empty()) c.distance[i] = e.distance[j];
      if (!c.light.empty()) c.light[i] = e.light[j];
      if (inside && y < e.height) {
        c.labels[i] = e.labels[j];
        c.excluded[i] = e.excluded[j];
      }
    }
  }
  return c;
}

}  // namespace maquette::synthesis
