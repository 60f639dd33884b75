// A small 5 x 7 pixel font (the project's own drawing) for legends: ASCII letters, digits and
// common signs; other characters are drawn as '?'.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

#include "image/rgba_image.h"

namespace maquette {

inline constexpr int kGlyphWidth = 5, kGlyphHeight = 7, kGlyphAdvance = 6;  // unscaled pixels

// Width in pixels of `text` drawn at `scale` (each font pixel a scale x scale square).
int text_width(std::string_view text, int scale);

// Draws `text` with its top-left corner at (col, row), clipped to the image.
void draw_text(RgbaImage& image, int col, int row, std::string_view text,
               const std::array<uint8_t, 3>& rgb, int scale);

}  // namespace maquette
