// Synthetic images and masks for the inpainting and clone tests.
#pragma once

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "../nearest_field.h"

namespace maquette::synthesis::test {

// width * height flags, 1 in the side x side square from (x0, y0).
inline std::vector<uint8_t> square_mask(int width, int height, int x0, int y0, int side) {
  std::vector<uint8_t> mask(size_t(width) * height, 0);
  for (int y = y0; y < y0 + side; ++y) {
    for (int x = x0; x < x0 + side; ++x) mask[size_t(y) * width + x] = 1;
  }
  return mask;
}

// An RGB image, each pixel the colour of its place in a period_x x period_y tile of random
// colours (drawn from `seed`).
inline PatchImage periodic_texture(int width, int height, int period_x, int period_y,
                                   uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> value(0, 255);
  std::vector<float> period(size_t(period_x) * period_y * 3);
  for (float& v : period) v = value(rng);
  PatchImage image(width, height, 3);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      std::copy_n(period.begin() + ((y % period_y) * period_x + x % period_x) * 3, 3,
                  image.pixel(x, y));
    }
  }
  return image;
}

}  // namespace maquette::synthesis::test
