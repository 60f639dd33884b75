#include "gdal/resample.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "core/error.h"

namespace maquette {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// floor for the window's coordinate range, without a libm call (the hot path).
inline int ifloor(double v) {
  const int i = int(v);
  return i - (v < i);
}

// Bilinear from the 2x2 pixels at (i, j)..(i + 1, j + 1) with fractions fu, fv.
float bilinear_at(const Window& w, int band, int i, int j, double fu, double fv) {
  // The common case: all four pixels in the window and valid.
  if (i >= 0 && j >= 0 && i + 1 < w.w && j + 1 < w.h) {
    const float* p = w.planes[size_t(band)].data() + size_t(j) * size_t(w.w) + size_t(i);
    const float a = p[0], b = p[1], c = p[w.w], d = p[w.w + 1];
    if (!std::isnan(a + b + c + d))
      return float((1 - fv) * ((1 - fu) * a + fu * b) + fv * ((1 - fu) * c + fu * d));
  }
  const double wt[4] = {(1 - fu) * (1 - fv), fu * (1 - fv), (1 - fu) * fv, fu * fv};
  const float s[4] = {w.at(band, i, j), w.at(band, i + 1, j), w.at(band, i, j + 1),
                      w.at(band, i + 1, j + 1)};
  double sum = 0, norm = 0;
  for (int k = 0; k < 4; ++k)
    if (!std::isnan(s[k]) && wt[k] > 0) {
      sum += wt[k] * s[k];
      norm += wt[k];
    }
  return norm > 0 ? float(sum / norm) : kNaN;
}

float bilinear(const Window& w, int band, double x, double y) {
  const double u = x - 0.5, v = y - 0.5;
  const int i = ifloor(u), j = ifloor(v);
  return bilinear_at(w, band, i, j, u - i, v - j);
}

void keys(double t, double out[4]) {  // weights of pixels -1, 0, 1, 2 for offset t in [0, 1)
  constexpr double a = -0.5;
  const auto near = [&](double d) { return ((a + 2) * d - (a + 3)) * d * d + 1; };
  const auto far = [&](double d) { return ((a * d - 5 * a) * d + 8 * a) * d - 4 * a; };
  out[0] = far(1 + t);
  out[1] = near(t);
  out[2] = near(1 - t);
  out[3] = far(2 - t);
}

float cubic(const Window& w, int band, double x, double y) {
  const double u = x - 0.5, v = y - 0.5;
  const int i = ifloor(u), j = ifloor(v);
  double wu[4], wv[4];
  keys(u - i, wu);
  keys(v - j, wv);
  double sum = 0;
  for (int b = 0; b < 4; ++b) {
    double row = 0;
    for (int a = 0; a < 4; ++a) {
      const float s = w.at(band, i - 1 + a, j - 1 + b);
      if (std::isnan(s)) return bilinear(w, band, x, y);
      row += wu[a] * s;
    }
    sum += wv[b] * row;
  }
  return float(sum);
}

// Calls visit(value, weight) for every pixel under the box, weighted by the overlapped area.
template <typename Visit>
void box(const Window& w, int band, double x, double y, double hx, double hy, Visit visit) {
  hx = std::max(hx, 0.5);
  hy = std::max(hy, 0.5);
  const double x0 = x - hx, x1 = x + hx, y0 = y - hy, y1 = y + hy;
  for (int j = int(std::floor(y0)); j < int(std::ceil(y1)); ++j) {
    const double fy = std::min<double>(y1, j + 1) - std::max<double>(y0, j);
    for (int i = int(std::floor(x0)); i < int(std::ceil(x1)); ++i) {
      const float s = w.at(band, i, j);
      if (!std::isnan(s)) visit(s, fy * (std::min<double>(x1, i + 1) - std::max<double>(x0, i)));
    }
  }
}

float average(const Window& w, int band, double x, double y, double hx, double hy) {
  double sum = 0, norm = 0;
  box(w, band, x, y, hx, hy, [&](float s, double wt) {
    sum += wt * s;
    norm += wt;
  });
  return norm > 0 ? float(sum / norm) : kNaN;
}

float mode(const Window& w, int band, double x, double y, double hx, double hy) {
  thread_local std::vector<std::pair<float, double>> votes;
  votes.clear();
  box(w, band, x, y, hx, hy, [&](float s, double wt) {
    for (auto& [value, weight] : votes)
      if (value == s) {
        weight += wt;
        return;
      }
    votes.emplace_back(s, wt);
  });
  float best = kNaN;
  double best_weight = 0;
  for (const auto& [value, weight] : votes)
    if (weight > best_weight || (weight == best_weight && value < best)) {
      best = value;
      best_weight = weight;
    }
  return best;
}

}  // namespace

std::string_view resampling_name(Resampling r) {
  switch (r) {
    case Resampling::Nearest:
      return "nearest";
    case Resampling::Bilinear:
      return "bilinear";
    case Resampling::Cubic:
      return "cubic";
    case Resampling::Mode:
      return "mode";
    case Resampling::Average:
      return "average";
  }
  return "?";
}

Resampling parse_resampling(std::string_view name) {
  for (Resampling r : {Resampling::Nearest, Resampling::Bilinear, Resampling::Cubic,
                       Resampling::Mode, Resampling::Average})
    if (resampling_name(r) == name) return r;
  throw Error("--resampling '" + std::string(name) +
              "' is not one of nearest, bilinear, cubic, mode, average");
}

void resample(const Window& w, Resampling r, const WindowPoints& p, std::span<float> out) {
  const size_t bands = w.planes.size();
  const double x0 = double(w.x0), y0 = double(w.y0), step = w.step;
  // Source pixels to window pixels (no division in the usual case of a full-resolution window).
  const auto scaled = [&](double v) { return w.step == 1 ? v : v / step; };
  // Calls value(i, band, x, y) with the window coordinates of each sample still missing.
  const auto fill = [&](auto value) {
    for (size_t i = 0; i < p.x.size(); ++i) {
      if (std::isnan(p.x[i])) continue;
      const double x = scaled(p.x[i] - x0), y = scaled(p.y[i] - y0);
      float* o = out.data() + i * bands;
      for (size_t b = 0; b < bands; ++b)
        if (std::isnan(o[b])) o[b] = value(i, int(b), x, y);
    }
  };
  switch (r) {
    case Resampling::Nearest:
      return fill([&](size_t, int b, double x, double y) {
        return w.at(b, int(std::floor(x)), int(std::floor(y)));
      });
    case Resampling::Bilinear:
      // The taps and fractions once per sample.
      for (size_t i = 0; i < p.x.size(); ++i) {
        if (std::isnan(p.x[i])) continue;
        const double u = scaled(p.x[i] - x0) - 0.5, v = scaled(p.y[i] - y0) - 0.5;
        const int col = ifloor(u), row = ifloor(v);
        const double fu = u - col, fv = v - row;
        float* o = out.data() + i * bands;
        for (size_t b = 0; b < bands; ++b)
          if (std::isnan(o[b])) o[b] = bilinear_at(w, int(b), col, row, fu, fv);
      }
      return;
    case Resampling::Cubic:
      return fill([&](size_t, int b, double x, double y) { return cubic(w, b, x, y); });
    case Resampling::Mode:
      return fill([&](size_t i, int b, double x, double y) {
        return mode(w, b, x, y, scaled(p.hx[i]), scaled(p.hy[i]));
      });
    case Resampling::Average:
      return fill([&](size_t i, int b, double x, double y) {
        return average(w, b, x, y, scaled(p.hx[i]), scaled(p.hy[i]));
      });
  }
}

}  // namespace maquette
