#include "masked_pyramid.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace maquette::synthesis {
namespace {

constexpr std::array<float, 5> kBinomial = {1, 4, 6, 4, 1};

MaskedImage halve(const MaskedImage& fine) {
  const PatchImage& f = fine.image;
  const int w = (f.width + 1) / 2, h = (f.height + 1) / 2, c = f.channels;
  MaskedImage coarse{PatchImage(w, h, c), halve_mask(fine.unknown, f.width, f.height)};
  std::vector<double> sum(c);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      std::fill(sum.begin(), sum.end(), 0.0);
      double weight = 0;
      for (int dy = -2; dy <= 2; ++dy) {
        const int fy = 2 * y + dy;
        if (fy < 0 || fy >= f.height) continue;
        for (int dx = -2; dx <= 2; ++dx) {
          const int fx = 2 * x + dx;
          if (fx < 0 || fx >= f.width || fine.unknown[size_t(fy) * f.width + fx] != 0) continue;
          const double k = kBinomial[dy + 2] * kBinomial[dx + 2];
          const float* v = f.pixel(fx, fy);
          for (int i = 0; i < c; ++i) sum[i] += k * v[i];
          weight += k;
        }
      }
      float* out = coarse.image.pixel(x, y);
      for (int i = 0; i < c; ++i) out[i] = weight > 0 ? float(sum[i] / weight) : 0.0f;
      if (weight == 0) coarse.unknown[size_t(y) * w + x] = 1;
    }
  }
  return coarse;
}

}  // namespace

std::vector<uint8_t> halve_mask(const std::vector<uint8_t>& mask, int width, int height) {
  const int w = (width + 1) / 2, h = (height + 1) / 2;
  std::vector<uint8_t> coarse(size_t(w) * h, 0);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      if (mask[size_t(y) * width + x] != 0) coarse[size_t(y / 2) * w + x / 2] = 1;
    }
  }
  return coarse;
}

std::vector<MaskedImage> masked_pyramid(MaskedImage base, int levels) {
  std::vector<MaskedImage> pyramid;
  pyramid.push_back(std::move(base));
  while (int(pyramid.size()) < levels) pyramid.push_back(halve(pyramid.back()));
  return pyramid;
}

std::vector<int32_t> chessboard_distance(const std::vector<uint8_t>& mask, int width, int height) {
  const int32_t far = width + height + 1;
  std::vector<int32_t> d(mask.size());
  for (size_t i = 0; i < mask.size(); ++i) d[i] = mask[i] != 0 ? 0 : far;
  const auto at = [&](int x, int y) -> int32_t& { return d[size_t(y) * width + x]; };
  // Two raster passes over the 8-neighbourhood: exact for the chessboard metric.
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      int32_t& v = at(x, y);
      if (x > 0) v = std::min(v, at(x - 1, y) + 1);
      if (y > 0) {
        for (int dx = -1; dx <= 1; ++dx) {
          if (x + dx >= 0 && x + dx < width) v = std::min(v, at(x + dx, y - 1) + 1);
        }
      }
    }
  }
  for (int y = height - 1; y >= 0; --y) {
    for (int x = width - 1; x >= 0; --x) {
      int32_t& v = at(x, y);
      if (x + 1 < width) v = std::min(v, at(x + 1, y) + 1);
      if (y + 1 < height) {
        for (int dx = -1; dx <= 1; ++dx) {
          if (x + dx >= 0 && x + dx < width) v = std::min(v, at(x + dx, y + 1) + 1);
        }
      }
    }
  }
  return d;
}

void fill_by_diffusion(PatchImage& image, std::vector<uint8_t> mask) {
  const int w = image.width, h = image.height, c = image.channels;
  std::vector<size_t> layer;
  std::vector<float> values;
  while (true) {
    layer.clear();
    values.clear();
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        if (mask[size_t(y) * w + x] == 0) continue;
        std::vector<double> sum(c, 0.0);
        int n = 0;
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            const int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= w || ny >= h || mask[size_t(ny) * w + nx] != 0) continue;
            for (int i = 0; i < c; ++i) sum[i] += image.pixel(nx, ny)[i];
            ++n;
          }
        }
        if (n == 0) continue;
        layer.push_back(size_t(y) * w + x);
        for (int i = 0; i < c; ++i) values.push_back(float(sum[i] / n));
      }
    }
    if (layer.empty()) return;
    for (size_t k = 0; k < layer.size(); ++k) {
      std::copy_n(values.begin() + k * c, c, image.values.begin() + layer[k] * c);
      mask[layer[k]] = 0;
    }
  }
}

void sample_bilinear(const PatchImage& image, double x, double y, float* out) {
  x = std::clamp(x, 0.0, double(image.width - 1));
  y = std::clamp(y, 0.0, double(image.height - 1));
  const int x0 = int(x), y0 = int(y);
  const int x1 = std::min(x0 + 1, image.width - 1), y1 = std::min(y0 + 1, image.height - 1);
  const double tx = x - x0, ty = y - y0;
  for (int c = 0; c < image.channels; ++c) {
    const double top = image.pixel(x0, y0)[c] * (1 - tx) + image.pixel(x1, y0)[c] * tx;
    const double bottom = image.pixel(x0, y1)[c] * (1 - tx) + image.pixel(x1, y1)[c] * tx;
    out[c] = float(top * (1 - ty) + bottom * ty);
  }
}

void upsample_into(const PatchImage& coarse, const std::vector<uint8_t>& where, PatchImage& fine) {
  for (int y = 0; y < fine.height; ++y)
    for (int x = 0; x < fine.width; ++x)
      if (where[size_t(y) * fine.width + x] != 0)
        sample_bilinear(coarse, x / 2.0 - 0.25, y / 2.0 - 0.25, fine.pixel(x, y));
}

}  // namespace maquette::synthesis
