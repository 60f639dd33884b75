#include "image/quicklook.h"

#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <vector>

#include "core/error.h"
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

void write_png(const cv::Mat& image, const std::string& path) {
  bool ok = false;
  try {
    ok = cv::imwrite(path, image);
  } catch (const cv::Exception& e) {
    throw Error("cannot write " + path + ": " + e.what());
  }
  if (!ok) throw Error("cannot write " + path);
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

  cv::Mat image(m.height, m.width, CV_8UC4, cv::Scalar(0, 0, 0, 0));
  for (int r = 0; r < m.height; ++r) {
    auto* px = image.ptr<cv::Vec4b>(r);
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
      px[c] = cv::Vec4b(colour[2], colour[1], colour[0], 255);  // OpenCV stores BGRA
    }
  }
  write_png(image, path);
}

}  // namespace maquette
