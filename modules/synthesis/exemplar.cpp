#include "exemplar.h"

#include <algorithm>

namespace maquette::synthesis {

Exemplar shrink_exemplar(const Exemplar& e, int factor) {
  if (factor == 1) return e;
  Exemplar s;
  s.width = std::max(1, e.width / factor);
  s.height = std::max(1, e.height / factor);
  const size_t n = size_t(s.width) * size_t(s.height);
  s.rgb.assign(3 * n, 0.0f);
  s.labels.assign(n, 0);
  s.excluded.assign(n, 0);
  if (!e.altitude.empty()) s.altitude.assign(n, 0.0f);
  if (!e.distance.empty()) s.distance.assign(n, 0.0f);
  if (!e.light.empty()) s.light.assign(n, 0.0f);
  const float area = float(factor * factor);
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x) {
      const size_t i = size_t(y) * size_t(s.width) + size_t(x);
      const size_t corner = size_t(y * factor) * size_t(e.width) + size_t(x * factor);
      s.labels[i] = e.labels[corner];
      for (int dy = 0; dy < factor; ++dy)
        for (int dx = 0; dx < factor; ++dx) {
          const size_t j = corner + size_t(dy) * size_t(e.width) + size_t(dx);
          for (int c = 0; c < 3; ++c) s.rgb[3 * i + size_t(c)] += e.rgb[3 * j + size_t(c)] / area;
          s.excluded[i] |= e.excluded[j];
          if (!e.altitude.empty()) s.altitude[i] += e.altitude[j] / area;
          if (!e.distance.empty()) s.distance[i] += e.distance[j] / area;
          if (!e.light.empty()) s.light[i] += e.light[j] / area;
        }
    }
  return s;
}

}  // namespace maquette::synthesis
