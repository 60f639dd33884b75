#include "gltf/texture_image.h"

#include "gdal/image_file.h"

namespace maquette {

EncodedImage encode_texture(const Tile<uint8_t>& tile) {
  const bool rgb = tile.channels() == 3;
  static const ImageFormat jpeg{"JPEG", {"QUALITY=90"}}, png{"PNG", {}};
  return {rgb ? "image/jpeg" : "image/png",
          encode_image(tile.data(), tile.size(), tile.size(), tile.channels(), rgb ? jpeg : png)};
}

}  // namespace maquette
