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
        }
    }
  s.altitude = shrink_band(e.altitude, e.width, e.height, factor);
  s.distance = shrink_band(e.distance, e.width, e.height, factor);
  s.light = shrink_band(e.light, e.width, e.height, factor);
  return s;
}

std::vector<float> shrink_band(const std::vector<float>& band, int width, int height, int factor) {
  if (band.empty() || factor == 1) return band;
  const int w = std::max(1, width / factor), h = std::max(1, height / factor);
  std::vector<float> out(size_t(w) * size_t(h), 0.0f);
  const float area = float(factor * factor);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t corner = size_t(y * factor) * size_t(width) + size_t(x * factor);
      for (int dy = 0; dy < factor; ++dy)
        for (int dx = 0; dx < factor; ++dx)
          out[size_t(y) * size_t(w) + size_t(x)] +=
              band[corner + size_t(dy) * size_t(width) + size_t(dx)] / area;
    }
  return out;
}

}  // namespace maquette::synthesis
