// 8-bit PNG images for the synthesis tests, written by GDAL (a MEM dataset copied by the PNG
// driver).
#pragma once

#include <functional>
#include <string>

namespace maquette::test {

// Writes `path`: `bands` bands of width x height, band b's pixel (x, y) value(x, y, b) rounded
// and clamped to 0..255 (b from 0). Returns `path`.
std::string write_png(const std::string& path, int width, int height, int bands,
                      const std::function<double(int x, int y, int band)>& value);

}  // namespace maquette::test
