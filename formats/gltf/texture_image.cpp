#include "gltf/texture_image.h"

#include <vector>

#include "gdal/image_file.h"

namespace maquette {

EncodedImage encode_texture(const Tile<uint8_t>& tile) {
  const bool rgb = tile.channels() == 3;
  static const ImageFormat jpeg{"JPEG", {"QUALITY=90"}}, png{"PNG", {}};
  return {rgb ? "image/jpeg" : "image/png",
          encode_image(tile.data(), tile.size(), tile.size(), tile.channels(), rgb ? jpeg : png)};
}

void pad_no_data(Tile<uint8_t>& tile, uint8_t nodata) {
  struct Level {
    int size;
    std::vector<float> sum, weight;  // per sample: the sum of the data's values, their count
  };
  const int colours = tile.channels() == 4 ? 3 : tile.channels();  // alpha stays as it is
  for (int k = 0; k < colours; ++k) {
    std::vector<Level> levels{{tile.size(), {}, {}}};
    for (int r = 0; r < tile.size(); ++r)
      for (int c = 0; c < tile.size(); ++c) {
        const uint8_t v = tile.at(c, r, k);
        levels[0].sum.push_back(v == nodata ? 0.0f : float(v));
        levels[0].weight.push_back(v == nodata ? 0.0f : 1.0f);
      }
    while (levels.back().size > 1) {  // pull: sums over 2 x 2 blocks
      const Level& fine = levels.back();
      Level coarse{fine.size / 2, std::vector<float>(size_t(fine.size / 2) * (fine.size / 2)),
                   std::vector<float>(size_t(fine.size / 2) * (fine.size / 2))};
      for (int r = 0; r < coarse.size; ++r)
        for (int c = 0; c < coarse.size; ++c)
          for (int i : {0, 1})
            for (int j : {0, 1}) {
              const size_t f = size_t(2 * r + i) * fine.size + size_t(2 * c + j);
              coarse.sum[size_t(r) * coarse.size + c] += fine.sum[f];
              coarse.weight[size_t(r) * coarse.size + c] += fine.weight[f];
            }
      levels.push_back(std::move(coarse));
    }
    if (levels.back().weight.front() == 0) continue;  // no data in this channel
    for (size_t l = levels.size() - 1; l-- > 0;) {    // push: means into blocks without data
      Level& fine = levels[l];
      const Level& coarse = levels[l + 1];
      for (int r = 0; r < fine.size; ++r)
        for (int c = 0; c < fine.size; ++c) {
          const size_t f = size_t(r) * fine.size + c, p = size_t(r / 2) * coarse.size + c / 2;
          if (fine.weight[f] == 0) {
            fine.sum[f] = coarse.sum[p] / coarse.weight[p];
            fine.weight[f] = 1;
          }
        }
    }
    const Level& base = levels.front();  // every sample has a value now (weight 1 if no data)
    for (int r = 0; r < tile.size(); ++r)
      for (int c = 0; c < tile.size(); ++c) {
        uint8_t& v = tile.at(c, r, k);
        if (v != nodata) continue;
        // A mean of bytes; kept off nodata itself so that it reads as data.
        const int mean =
            int(base.sum[size_t(r) * tile.size() + c] / base.weight[size_t(r) * tile.size() + c] +
                0.5f);
        v = uint8_t(mean == nodata ? (nodata < 255 ? nodata + 1 : 254) : mean);
      }
  }
}

}  // namespace maquette
