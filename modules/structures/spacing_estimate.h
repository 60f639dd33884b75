// The average spacing of plants seen from above (the paper's future work in §5: "provided
// automatically"), by frequency analysis: crowns repeat at about their spacing, so the image's
// power spectrum, averaged over directions, peaks at the frequency 1 / spacing (for a square
// lattice of crowns exactly; for a hexagonal one at 2 / (sqrt(3) d), 7 % under the spacing of
// its density).
//
// The image (e.g. the orthophoto's luminance) has its mean removed and a Hann window applied,
// is zero-padded to a square of a power of two and transformed (Eigen's FFT); the power is summed
// in rings of width one frequency step. Ring sums of images of one size add up (Welch's method:
// the tiles of a stroke, summed by a reduce step); the ring of the highest mean power between
// spacings of 2.5 pixels and a quarter of the side, when it is a peak (above both neighbours,
// not at an end of that range), refined by a parabola through it and its neighbours, gives the
// spacing. Tested on synthetic images only (crowns, with and without a brightness gradient).
#pragma once

#include <vector>

namespace maquette::structures {

// How a pixel step lies on the ground: metres east and north of one step along a row (the next
// column) and of one step down a column (the next row). rHEALPix pixels are equal-area but not
// square on the ground (at 37 degrees on an equatorial face: 0.8 times as wide as high), so
// frequencies are measured in metres, not pixels.
struct PixelAxes {
  double col_east = 1, col_north = 0, row_east = 0, row_north = -1;
  double area_side() const;  // sqrt of the pixel's area (metres)
};

// The power of an image's spectrum by ring: ring k holds the frequencies within half a step of
// k cycles per `side` x PixelAxes::area_side() metres.
struct RingPower {
  int side = 0;                      // the padded side (a power of two)
  std::vector<double> power, count;  // by ring: summed power, frequencies summed
};

// Of one image (row-major, width x height, NaN where unknown: those pixels count as the mean).
// Preconditions: width, height >= 1, some finite value.
RingPower ring_power(const std::vector<float>& image, int width, int height,
                     const PixelAxes& axes = {});
// Adds `b` to `a` (the same side).
void add_rings(RingPower& a, const RingPower& b);
// The spacing in metres at the rings' peak; pixel_m: the images' PixelAxes::area_side() (1 for
// the default axes: the spacing in pixels). Precondition: pixel_m > 0. Throws
// std::runtime_error when the side is under 16, the images were uniform, or the highest ring is
// at an end of the range rather than a peak (no crowns at a regular spacing).
double spacing_from_rings(const RingPower& rings, double pixel_m);

// The spacing in metres of the crowns of one image: spacing_from_rings(ring_power(...)).
double estimate_spacing(const std::vector<float>& image, int width, int height, double pixel_m);

}  // namespace maquette::structures
