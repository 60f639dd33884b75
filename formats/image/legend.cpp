#include "image/legend.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "image/bitmap_font.h"

namespace maquette {
namespace {

constexpr Rgb kPaper = {255, 255, 255}, kInk = {30, 30, 30};

std::string label(double v, double step) {
  const int decimals = step >= 1 ? 0 : int(std::ceil(-std::log10(step) - 1e-9));
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", decimals, std::abs(v) < step * 1e-6 ? 0.0 : v);
  return text;
}

// The map's pixels copied into a taller (and maybe wider) image with a white margin below.
RgbaImage with_margin(RgbaImage& map, int width, int margin) {
  RgbaImage out(std::max(map.width, width), map.height + margin);
  for (int r = 0; r < map.height; ++r)
    std::copy_n(map.at(0, r), size_t(map.width) * 4, out.at(0, r));
  out.fill(0, map.height, out.width, margin, kPaper);
  return out;
}

void draw_bar(RgbaImage& image, const ColourBar& bar, int s) {
  const int pad = 6 * s, bar_h = 10 * s, tick = 3 * s, text_h = kGlyphHeight * s;
  const int units_w = bar.units.empty() ? 0 : text_width(bar.units, s) + pad;
  const int width = std::max(image.width, 160 * s);
  const int bar_w = width - 2 * pad - units_w;
  const int top = image.height + pad;
  RgbaImage out = with_margin(image, width, 2 * pad + bar_h + tick + s + text_h);
  const double span = bar.high - bar.low;
  auto colour_at = [&](double f) {
    return bar.ramp == Ramp::Hypsometric ? ramp_colour(bar.ramp, bar.low + f * span)
                                         : ramp_colour(bar.ramp, f);
  };
  for (int c = 0; c < bar_w; ++c) out.fill(pad + c, top, 1, bar_h, colour_at((c + 0.5) / bar_w));
  if (!bar.units.empty())
    draw_text(out, pad + bar_w + pad, top + (bar_h - text_h) / 2, bar.units, kInk, s);
  // As many ticks as labels of the widest value fit side by side.
  const int label_w = text_width(label(bar.high, span) + "-0", s) + 4 * s;
  const std::vector<double> ticks = nice_ticks(bar.low, bar.high, std::max(2, bar_w / label_w));
  const double step = ticks.size() > 1 ? ticks[1] - ticks[0] : span;
  for (double v : ticks) {
    const int x = pad + int(std::lround((v - bar.low) / span * (bar_w - 1)));
    out.fill(x, top + bar_h, s, tick, kInk);
    const std::string text = label(v, step);
    const int w = text_width(text, s);
    draw_text(out, std::clamp(x - w / 2, 0, out.width - w), top + bar_h + tick + s, text, kInk, s);
  }
  image = std::move(out);
}

void draw_classes(RgbaImage& image, const ClassKey& key, int s) {
  const int pad = 6 * s, swatch = kGlyphHeight * s, line = swatch + 4 * s;
  const int width = std::max(image.width, 160 * s);
  // Entries flow left to right, wrapping to new lines.
  std::vector<std::pair<int, int>> at;  // x, line
  int x = pad, lines = key.empty() ? 0 : 1;
  for (const auto& [colour, name] : key) {
    const int w = swatch + 3 * s + text_width(name, s) + 3 * pad;
    if (x > pad && x + w - 2 * pad > width - pad) x = pad, ++lines;
    at.emplace_back(x, lines - 1);
    x += w;
  }
  RgbaImage out = with_margin(image, width, 2 * pad + lines * line - 4 * s);
  for (size_t i = 0; i < key.size(); ++i) {
    const int left = at[i].first, top = image.height + pad + at[i].second * line;
    out.fill(left, top, swatch, swatch, kInk);
    out.fill(left + s, top + s, swatch - 2 * s, swatch - 2 * s, key[i].first);
    draw_text(out, left + swatch + 3 * s, top, key[i].second, kInk, s);
  }
  image = std::move(out);
}

}  // namespace

std::vector<double> nice_ticks(double low, double high, int max_ticks) {
  const double span = high - low;
  if (!(span > 0) || max_ticks < 2) return {low};
  const double unit = std::pow(10.0, std::floor(std::log10(span / max_ticks)));
  double step = unit;
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (step = m * unit; std::floor(high / step) - std::ceil(low / step) + 1 <= max_ticks) break;
  std::vector<double> ticks;
  for (double k = std::ceil(low / step - 1e-9); k * step <= high + step * 1e-9; ++k)
    ticks.push_back(k * step);
  return ticks;
}

void add_legend(RgbaImage& image, const Legend& legend) {
  const int s = std::min(4, 1 + image.width / 400);
  if (const auto* bar = std::get_if<ColourBar>(&legend))
    draw_bar(image, *bar, s);
  else
    draw_classes(image, std::get<ClassKey>(legend), s);
}

}  // namespace maquette
