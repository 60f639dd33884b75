#include "image/quicklook.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.h"
#include "gdal/image_file.h"
#include "image/hillshade.h"

namespace maquette {
namespace {

// The 2nd and 98th percentiles of the finite values of one channel.
std::pair<double, double> percentile_range(const LonLatRaster& m, int channel) {
  std::vector<float> v;
  v.reserve(size_t(m.width) * size_t(m.height));
  for (int r = 0; r < m.height; ++r)
    for (int c = 0; c < m.width; ++c)
      if (const float x = m.at(c, r, channel); std::isfinite(x)) v.push_back(x);
  if (v.empty()) return {0.0, 1.0};
  auto nth = [&](double q) {
    auto it = v.begin() + std::ptrdiff_t(q * double(v.size() - 1));
    std::nth_element(v.begin(), it, v.end());
    return double(*it);
  };
  const double lo = nth(0.02), hi = nth(0.98);
  return {lo, hi > lo ? hi : lo + 1.0};
}

// The channels drawn: the chosen bands for imagery, else channel 0.
std::vector<int> drawn_channels(const LonLatRaster& m, const QuicklookStyle& style) {
  if (style.classes || m.channels < 3) return {0};
  std::vector<int> bands = style.bands.empty() ? std::vector<int>{0, 1, 2} : style.bands;
  if (bands.size() != 3) throw Error("--bands needs three bands (R,G,B)");
  for (int b : bands)
    if (b < 0 || b >= m.channels)
      throw Error("band " + std::to_string(b + 1) + " out of range: the layer has " +
                  std::to_string(m.channels) + " channels");
  return bands;
}

}  // namespace

void write_quicklook_png(const LonLatRaster& m, const QuicklookStyle& style,
                         const std::string& path) {
  const std::vector<int> channels = drawn_channels(m, style);
  const bool rgb = channels.size() == 3;
  std::vector<std::pair<double, double>> ranges;
  if (!style.classes)
    for (int k : channels) ranges.push_back(style.range ? *style.range : percentile_range(m, k));
  const std::vector<float> shade =
      style.hillshade && !rgb && !style.classes ? hillshade(m) : std::vector<float>{};

  std::vector<uint8_t> image(size_t(m.width) * size_t(m.height) * 4, 0);  // RGBA, transparent
  for (int r = 0; r < m.height; ++r) {
    uint8_t* row = image.data() + size_t(r) * size_t(m.width) * 4;
    for (int c = 0; c < m.width; ++c) {
      const float v0 = m.at(c, r, channels[0]);
      if (!std::isfinite(v0)) continue;
      auto t = [&](size_t k) {
        return (m.at(c, r, channels[k]) - ranges[k].first) / (ranges[k].second - ranges[k].first);
      };
      Rgb colour{};
      if (style.classes) {
        colour = class_colour(*style.classes, std::llround(v0));
      } else if (rgb) {
        for (size_t k = 0; k < 3; ++k)
          colour[k] = uint8_t(std::lround(255.0 * std::clamp(t(k), 0.0, 1.0)));
      } else {
        colour = ramp_colour(style.ramp, t(0));
      }
      if (!shade.empty()) {
        const float s = shade[size_t(r) * size_t(m.width) + size_t(c)];
        for (auto& x : colour) x = uint8_t(std::lround(x * s));
      }
      std::copy(colour.begin(), colour.end(), row + 4 * c);
      row[4 * c + 3] = 255;
    }
  }
  write_image(image, m.width, m.height, 4, {"PNG", {}}, path);
}

}  // namespace maquette
