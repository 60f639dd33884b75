#include "hs_plot.h"

#include <algorithm>
#include <cmath>

#include "hs_histogram.h"
#include "image/quicklook.h"

namespace maquette::texture {
namespace {

constexpr double kRimWidth = 0.05;               // saturation units beyond 1
constexpr int kMarkArm = 7, kMarkHalfWidth = 1;  // pixels

// A fully saturated, full-value hue (degrees) as RGB 0..255.
std::array<float, 3> pure_hue(double hue) {
  const double h = hue / 60;
  const double x = 1 - std::abs(std::fmod(h, 2) - 1);
  const std::array<std::array<double, 3>, 6> sextants = {
      {{1, x, 0}, {x, 1, 0}, {0, 1, x}, {0, x, 1}, {x, 0, 1}, {1, 0, x}}};
  const auto& c = sextants[size_t(std::clamp(int(h), 0, 5))];
  return {float(255 * c[0]), float(255 * c[1]), float(255 * c[2])};
}

}  // namespace

std::array<double, 2> plot_position(double hue, double saturation) {
  const double r = saturation * kPlotRadius * kPlotSize, a = hue * M_PI / 180;
  return {kPlotSize / 2.0 + r * std::cos(a), kPlotSize / 2.0 - r * std::sin(a)};
}

void write_hs_plot(const std::vector<uint64_t>& hs_counts, const std::vector<Hsv>& centres,
                   const std::string& path) {
  PictureRaster image;
  image.width = image.height = kPlotSize;
  image.channels = 3;
  image.values.assign(size_t(kPlotSize) * kPlotSize * 3, NAN);
  const double top = std::log1p(double(*std::max_element(hs_counts.begin(), hs_counts.end())));
  const auto set = [&](int col, int row, const std::array<float, 3>& rgb) {
    std::copy(rgb.begin(), rgb.end(),
              image.values.begin() + std::ptrdiff_t((size_t(row) * kPlotSize + size_t(col)) * 3));
  };
  for (int row = 0; row < kPlotSize; ++row)
    for (int col = 0; col < kPlotSize; ++col) {
      const double x = col + 0.5 - kPlotSize / 2.0, y = kPlotSize / 2.0 - (row + 0.5);
      const double s = std::hypot(x, y) / (kPlotRadius * kPlotSize);
      double hue = std::atan2(y, x) * 180 / M_PI;
      hue = hue < 0 ? std::fmod(hue + 360, 360) : hue;
      if (s > 1 + kRimWidth) continue;
      if (s > 1) {
        set(col, row, pure_hue(hue));
        continue;
      }
      const uint64_t n = hs_counts[size_t(colour_bin({hue, s, 0}, ColourSpace::Hs))];
      const auto grey = float(top > 0 ? std::round(255 * std::log1p(double(n)) / top) : 0);
      set(col, row, {grey, grey, grey});
    }
  const std::array<float, 3> mark = {kCentreMark[0], kCentreMark[1], kCentreMark[2]};
  for (const Hsv& c : centres) {
    const auto p = plot_position(c.h, c.s);
    const int col = int(std::floor(p[0])), row = int(std::floor(p[1]));
    for (int a = -kMarkArm; a <= kMarkArm; ++a)
      for (int w = -kMarkHalfWidth; w <= kMarkHalfWidth; ++w)
        for (const auto& [dc, dr] : {std::pair{a, w}, std::pair{w, a}})
          if (col + dc >= 0 && col + dc < kPlotSize && row + dr >= 0 && row + dr < kPlotSize)
            set(col + dc, row + dr, mark);
  }
  QuicklookStyle style;
  style.range = std::pair{0.0, 255.0};
  write_quicklook_png(image, style, path);
}

}  // namespace maquette::texture
