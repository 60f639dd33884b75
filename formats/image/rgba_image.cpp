#include "image/rgba_image.h"

#include <algorithm>

namespace maquette {

void RgbaImage::fill(int col, int row, int w, int h, const std::array<uint8_t, 3>& rgb) {
  for (int r = std::max(row, 0); r < std::min(row + h, height); ++r)
    for (int c = std::max(col, 0); c < std::min(col + w, width); ++c) {
      uint8_t* p = at(c, r);
      std::copy(rgb.begin(), rgb.end(), p);
      p[3] = 255;
    }
}

}  // namespace maquette
