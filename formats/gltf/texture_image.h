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

}  // namespace maquette
