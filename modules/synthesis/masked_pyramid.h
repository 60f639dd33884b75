// A Gaussian pyramid of an image with unknown pixels (a hole, nodata): each coarser level halves
// the sides (rounded up), its pixels the binomial 5 x 5 average of the known pixels beneath
// (weights renormalized over them); a coarser pixel is unknown when one of the 2 x 2 finer pixels
// it covers is (so the hole never shrinks on the way up), and the chessboard distances that
// decide the hole's band and the patches' roles.
#pragma once

#include <cstdint>
#include <vector>

#include "nearest_field.h"

namespace maquette::synthesis {

struct MaskedImage {
  PatchImage image;
  std::vector<uint8_t> unknown;  // width * height, non-zero: no value (the image holds anything)
};

// `mask` (width x height) at the next level up: a pixel is set when one of the 2 x 2 it covers is.
std::vector<uint8_t> halve_mask(const std::vector<uint8_t>& mask, int width, int height);

// Level 0 is `base`; each next level the one before halved, up to `levels` levels in all.
std::vector<MaskedImage> masked_pyramid(MaskedImage base, int levels);

// The chessboard distance from each pixel to the nearest pixel of `mask` (0 on it), or a value
// above width + height when the mask is empty.
std::vector<int32_t> chessboard_distance(const std::vector<uint8_t>& mask, int width, int height);

// Gives the pixels of `mask` (width * height) the mean of their known 8-neighbours, layer by layer
// from the known pixels inward (each layer from the state before it): a smooth provisional fill.
// Pixels out of reach of any known one keep their values.
void fill_by_diffusion(PatchImage& image, std::vector<uint8_t> mask);

// The value of `image` at fractional pixel (x, y) (pixel centres at integers), bilinear, the
// point clamped into the image (a NaN among the four pixels read gives NaN).
void sample_bilinear(const PatchImage& image, double x, double y, float* out);

// `fine` with its pixels in `where` set to `coarse` (the next level up) interpolated bilinearly,
// sample centres aligned (fine pixel x at coarse x / 2 - 0.25).
void upsample_into(const PatchImage& coarse, const std::vector<uint8_t>& where, PatchImage& fine);

}  // namespace maquette::synthesis
