// An 8-bit RGBA picture in memory, for quicklooks and what is drawn on them.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace maquette {

struct RgbaImage {
  int width = 0, height = 0;
  std::vector<uint8_t> pixels;  // row-major, 4 bytes per pixel, all 0 (transparent) at first

  RgbaImage() = default;
  RgbaImage(int w, int h) : width(w), height(h), pixels(size_t(w) * size_t(h) * 4, 0) {}
  uint8_t* at(int col, int row) {
    return pixels.data() + (size_t(row) * size_t(width) + size_t(col)) * 4;
  }
  // Sets the pixels of a rectangle (clipped to the image) to an opaque colour.
  void fill(int col, int row, int w, int h, const std::array<uint8_t, 3>& rgb);
};

}  // namespace maquette
