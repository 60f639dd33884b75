// Colour conversions: RGB -> HSV (paper 5.2.1), sRGB <-> CIELAB (D65; sRGB's transfer function is
// core/srgb.h's) and the CIEDE2000 colour difference (Sharma, Wu and Dalal 2005).
#pragma once

#include <array>

namespace maquette::texture {

struct Hsv {
  double h = 0;  // degrees [0, 360)
  double s = 0;  // [0, 1]
  double v = 0;  // [0, 1]
};

using Lab = std::array<double, 3>;  // L* 0..100, a*, b*

Hsv rgb_to_hsv(double r, double g, double b);                     // components 0..255
std::array<double, 3> srgb_to_lab(double r, double g, double b);  // components 0..255
// srgb_to_lab's inverse: the sRGB colour (components 0..255) of a CIELAB colour, each linear
// component clamped to [0, 1] first (a colour outside the gamut lands on its edge). Exact up to
// the forward and inverse matrices' 7 digits within the gamut: lab_to_srgb(srgb_to_lab(c)) is c
// within 1e-3.
std::array<double, 3> lab_to_srgb(const Lab& lab);
double ciede2000(const std::array<double, 3>& lab1, const std::array<double, 3>& lab2);

}  // namespace maquette::texture
