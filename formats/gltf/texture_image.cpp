#include "gltf/texture_image.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.h"

namespace maquette {

EncodedImage encode_texture(const Tile<uint8_t>& tile) {
  const int channels = tile.channels();
  const cv::Mat rgb(tile.size(), tile.size(), CV_8UC(channels),
                    const_cast<uint8_t*>(tile.data().data()));
  cv::Mat bgr = rgb;
  if (channels == 3) cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  if (channels == 4) cv::cvtColor(rgb, bgr, cv::COLOR_RGBA2BGRA);
  EncodedImage out;
  out.mime_type = channels == 3 ? "image/jpeg" : "image/png";
  const std::vector<int> params = {cv::IMWRITE_JPEG_QUALITY, 90};
  if (!cv::imencode(channels == 3 ? ".jpg" : ".png", bgr, out.bytes,
                    channels == 3 ? params : std::vector<int>{}))
    throw Error("could not encode a texture tile");
  return out;
}

}  // namespace maquette
