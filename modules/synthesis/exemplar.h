// An exemplar of the synthesis: a painting's pixels and its control masks, one value per pixel.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace maquette::synthesis {

// Labels are painting classes 0..254; kUnknownLabel marks a target pixel without a class (it
// then matches any exemplar label).
inline constexpr uint8_t kUnknownLabel = 255;

struct Exemplar {
  int width = 0, height = 0;
  std::vector<float> rgb;         // 3 per pixel, 0..255, row-major
  std::vector<uint8_t> labels;    // painting class per pixel (< kUnknownLabel)
  std::vector<float> altitude;    // [0, 1] per pixel, or empty: no altitude guide
  std::vector<uint8_t> excluded;  // 1: never copied (shadows, frame, lettering, sky)
  std::vector<float> distance;    // [0, 1] per pixel (1: far from the viewer), or empty
  std::vector<float> light;       // [0, 1] per pixel (1: the lightest of its class), or empty
};

// An exemplar colour 0..1 as the operators' 8-bit colour layers store it: 0 is their nodata, so
// a channel at 0 is written 1 (it would read back, and export, as a hole).
inline float colour_byte(float unit) { return std::max(1.0f, std::round(unit * 255.0f)); }

// The exemplar shrunk `factor` times (a power of two >= 1) by box averaging: colours,
// altitude, distance and light averaged, the label of each block its top-left pixel's, a block
// excluded when any of its pixels is. Preconditions: the exemplar's vectors have its width x height
// pixels, and its width and height are at least `factor` (transfer_exemplar refuses a smaller
// painting).
Exemplar shrink_exemplar(const Exemplar& e, int factor);

// One band of `width` x `height` values shrunk `factor` times as shrink_exemplar shrinks the
// altitude: each block of factor x factor the mean of its values (a NaN among them: NaN). Empty
// stays empty.
std::vector<float> shrink_band(const std::vector<float>& band, int width, int height, int factor);

}  // namespace maquette::synthesis
