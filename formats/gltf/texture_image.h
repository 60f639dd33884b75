// Imagery tiles as images embedded in GLB files: JPEG for RGB, PNG for grey and RGBA.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/tile.h"

namespace maquette {

struct EncodedImage {
  std::string mime_type;  // "image/jpeg" or "image/png"
  std::vector<uint8_t> bytes;
};

EncodedImage encode_texture(const Tile<uint8_t>& tile);

// Gives each no-data sample (== nodata, channel by channel) the colour of the data around it,
// by pull-push: averages of the samples with data over 2 x 2, 4 x 4, ... blocks, pushed down into
// the no-data samples from the finest block that has data. A mesh samples its texture with
// bilinear filtering and mipmaps, so texels beyond the data's edge are seen along it (a skirt
// hanging from the edge is all such texels): padded, they show the edge's colours, not black.
// Colour channels only (alpha stays). Precondition: the tile's size is a power of two. A channel
// without any data is left as it is.
void pad_no_data(Tile<uint8_t>& tile, uint8_t nodata);

}  // namespace maquette
