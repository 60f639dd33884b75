// A transfer's source map applied to other images of its paintings (synthesis.apply; ebsynth's
// "repeat", what issue 18 gives the `source` output for): each output pixel takes an image's value
// over the exemplar_scale block its colour was copied from, so layers drawn in a painting's frame
// (another version of the painting, a height or roughness map painted beside it, a class image)
// are transferred exactly as its colours are. A function of each pixel's source alone: the same
// bits for any tiling, thread, rank or window, and seamless wherever the transfer is.
#pragma once

#include <string>
#include <vector>

namespace maquette::synthesis {

// One image of a painting shrunk to the transfer's exemplar pixels: block (x, y) holds the image's
// painting pixels [x scale, (x + 1) scale) x [y scale, (y + 1) scale).
struct SourceImage {
  std::string path;
  int width = 0, height = 0;  // the image's own size, painting pixels
  int scale = 1;              // painting pixels per block (a side): the transfer's exemplar_scale
  int channels = 0;           // 3 (colours 0..255) or 1
  std::vector<float> blocks;  // (width / scale) x (height / scale) x channels, row-major
};

enum class BlockValue { Mean, Mode };

// The image's colours read as the transfer reads its painting (painting.h's read_painting: grey,
// RGB, RGBA or a palette; 8-bit, or 16-bit over 257) and averaged over each block as it shrinks it
// (shrink_exemplar): applied to the transfer's first painting itself, its colours bit for bit.
// Throws maquette::Error naming the file when read_painting does, or when the image is smaller
// than one block.
SourceImage colour_image(const std::string& path, int scale);

// A one-band image of any type GDAL reads (its nodata NaN): each block's mean (NaN when it holds a
// NaN), or with BlockValue::Mode its most frequent value (ties: the smallest; NaN not counted, a
// block of NaN only NaN), for classes. Throws maquette::Error naming the file when it has
// another count of bands or is smaller than one block.
SourceImage value_image(const std::string& path, int scale, BlockValue block);

// The `channels` values of images[painting] at the block whose top-left painting pixel is (col,
// row), written to `out`. Throws maquette::Error when `painting` has no image (painting >=
// images.size()), when col or row is no multiple of the scale (sources of another
// exemplar_scale), or when the block is not within the image (an image smaller than its painting),
// naming the image, its size and the pixel.
void block_at(const std::vector<SourceImage>& images, float col, float row, float painting,
              float* out);

}  // namespace maquette::synthesis
