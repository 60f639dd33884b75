#include "image/quicklook.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/error.h"

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

}  // namespace

void write_quicklook_png(const LonLatRaster& m, const QuicklookStyle& style, const std::string& path) {
  const bool rgb = m.channels >= 3;
  std::vector<std::pair<double, double>> ranges;
  for (int k = 0; k < (rgb ? 3 : 1); ++k) ranges.push_back(style.range ? *style.range : percentile_range(m, k));

  cv::Mat image(m.height, m.width, CV_8UC4, cv::Scalar(0, 0, 0, 0));
  for (int r = 0; r < m.height; ++r) {
    auto* px = image.ptr<cv::Vec4b>(r);
    for (int c = 0; c < m.width; ++c) {
      auto t = [&](int k) { return (m.at(c, r, k) - ranges[size_t(k)].first) / (ranges[size_t(k)].second - ranges[size_t(k)].first); };
      if (!std::isfinite(m.at(c, r, 0))) continue;
      std::array<uint8_t, 3> colour{};
      if (rgb) {
        for (int k = 0; k < 3; ++k) colour[size_t(k)] = uint8_t(std::lround(255.0 * std::clamp(t(k), 0.0, 1.0)));
      } else {
        colour = ramp_colour(style.ramp, t(0));
      }
      px[c] = cv::Vec4b(colour[2], colour[1], colour[0], 255);  // OpenCV stores BGRA
    }
  }
  bool ok = false;
  try {
    ok = cv::imwrite(path, image);
  } catch (const cv::Exception& e) {
    throw Error("cannot write " + path + ": " + e.what());
  }
  if (!ok) throw Error("cannot write " + path);
}

}  // namespace maquette
