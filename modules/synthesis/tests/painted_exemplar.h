// Synthetic exemplars for the synthesis tests.
#pragma once

#include <cstddef>

#include "../exemplar.h"

namespace maquette::synthesis::test {

// A width x height exemplar whose colours, labels and exclusion flags (and altitudes when
// `with_altitude`) are sized, then set pixel by pixel by paint(e, x, y, i), i = y * width + x.
template <class Paint>
Exemplar painted_exemplar(int width, int height, bool with_altitude, Paint paint) {
  Exemplar e;
  e.width = width;
  e.height = height;
  const size_t n = size_t(width) * size_t(height);
  e.rgb.resize(3 * n);
  e.labels.resize(n);
  e.excluded.resize(n);
  if (with_altitude) e.altitude.resize(n);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) paint(e, x, y, size_t(y) * size_t(width) + size_t(x));
  return e;
}

}  // namespace maquette::synthesis::test
