#include "apply_sources.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/error.h"
#include "exemplar.h"
#include "painting.h"

namespace maquette::synthesis {
namespace {

void require_blocks(const std::string& path, int width, int height, int scale) {
  if (width < scale || height < scale)
    throw Error(path + ": " + std::to_string(width) + " x " + std::to_string(height) +
                " pixels, smaller than one block of exemplar_scale " + std::to_string(scale));
}

// Each block's most frequent value, NaN not counted (ties: the smallest; none: NaN).
std::vector<float> block_modes(const std::vector<float>& band, int width, int height, int scale) {
  const int w = width / scale, h = height / scale;
  std::vector<float> out(size_t(w) * size_t(h));
  std::map<float, int> counts;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      counts.clear();
      for (int dy = 0; dy < scale; ++dy)
        for (int dx = 0; dx < scale; ++dx)
          if (const float v = band[size_t(y * scale + dy) * size_t(width) + size_t(x * scale + dx)];
              !std::isnan(v))
            ++counts[v];
      float mode = NAN;
      int most = 0;
      for (const auto& [value, count] : counts)  // ascending: the first of the most is the least
        if (count > most) mode = value, most = count;
      out[size_t(y) * size_t(w) + size_t(x)] = mode;
    }
  return out;
}

}  // namespace

SourceImage colour_image(const std::string& path, int scale) {
  const Exemplar painting = read_painting(path, "image");
  require_blocks(path, painting.width, painting.height, scale);
  return {path, painting.width, painting.height, scale, 3, shrink_exemplar(painting, scale).rgb};
}

SourceImage value_image(const std::string& path, int scale, BlockValue block) {
  int width = 0, height = 0;
  const std::vector<float> values = read_value_band(path, width, height, "value image");
  require_blocks(path, width, height, scale);
  return {path,
          width,
          height,
          scale,
          1,
          block == BlockValue::Mode ? block_modes(values, width, height, scale)
                                    : shrink_band(values, width, height, scale)};
}

void block_at(const std::vector<SourceImage>& images, float col, float row, float painting,
              float* out) {
  if (!(painting >= 0 && painting < float(images.size()) && painting == std::floor(painting)))
    throw Error("the source names painting " + std::to_string(painting) +
                ", and params.images gives " + std::to_string(images.size()) +
                " (one per painting: the transfer's painting, then each of its exemplars)");
  const SourceImage& image = images[size_t(painting)];
  const auto pixel = [&] {
    return "painting pixel (" + std::to_string(int64_t(col)) + ", " + std::to_string(int64_t(row)) +
           ")";
  };
  const int w = image.width / image.scale, h = image.height / image.scale;
  const bool inside =
      col >= 0 && row >= 0 && col < float(w * image.scale) && row < float(h * image.scale);
  if (inside &&
      (std::fmod(col, float(image.scale)) != 0 || std::fmod(row, float(image.scale)) != 0))
    throw Error("the source names " + pixel() + ", which starts no block of exemplar_scale " +
                std::to_string(image.scale) + ": give the transfer's exemplar_scale");
  const int x = int(col) / image.scale, y = int(row) / image.scale;
  if (!inside)
    throw Error(image.path + ": " + std::to_string(image.width) + " x " +
                std::to_string(image.height) + " pixels, and the source names " + pixel() +
                ": the image must have its painting's size");
  std::copy_n(image.blocks.begin() + (ptrdiff_t(y) * w + x) * image.channels, image.channels, out);
}

}  // namespace maquette::synthesis
