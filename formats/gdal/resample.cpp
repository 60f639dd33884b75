#include "gdal/resample.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "core/error.h"
#include "gdal/resample_kernels.h"

namespace maquette {
namespace {

using namespace resample_detail;

// Bilinear at the window coordinates (u, v) = (x - 0.5, y - 0.5), for every band still NaN in
// o (a sample's bands).
void bilinear_point(const Window& w, double u, double v, float* o) {
  const int col = ifloor(u), row = ifloor(v);
  const double fu = u - col, fv = v - row;
  for (size_t b = 0; b < w.planes.size(); ++b)
    if (std::isnan(o[b])) o[b] = bilinear_at(w, int(b), col, row, fu, fv);
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
  // Calls value(i, band, x, y) with the window coordinates of each sample from `begin` on still
  // missing.
  const auto fill = [&](size_t begin, auto value) {
    for (size_t i = begin; i < p.x.size(); ++i) {
      if (std::isnan(p.x[i])) continue;
      const double x = scaled(p.x[i] - x0), y = scaled(p.y[i] - y0);
      float* o = out.data() + i * bands;
      for (size_t b = 0; b < bands; ++b)
        if (std::isnan(o[b])) o[b] = value(i, int(b), x, y);
    }
  };
  switch (r) {
    case Resampling::Nearest: {
      size_t i = 0;
      if (__builtin_cpu_supports("avx2")) nearest4(w, p, i = p.x.size() / 4 * 4, out);
      return fill(i, [&](size_t, int b, double x, double y) {
        return w.at(b, int(std::floor(x)), int(std::floor(y)));
      });
    }
    case Resampling::Bilinear: {
      // The taps and fractions once per sample; four at a time where the CPU has AVX2.
      size_t i = 0;
      if (__builtin_cpu_supports("avx2")) bilinear4(w, p, i = p.x.size() / 4 * 4, out);
      for (; i < p.x.size(); ++i)
        if (!std::isnan(p.x[i]))
          bilinear_point(w, scaled(p.x[i] - x0) - 0.5, scaled(p.y[i] - y0) - 0.5,
                         out.data() + i * bands);
      return;
    }
    case Resampling::Cubic: {
      size_t i = 0;
      if (__builtin_cpu_supports("avx2")) cubic4(w, p, i = p.x.size() / 4 * 4, out);
      return fill(i, [&](size_t, int b, double x, double y) { return cubic(w, b, x, y); });
    }
    case Resampling::Mode:
      return fill(0, [&](size_t i, int b, double x, double y) {
        return mode(w, b, x, y, scaled(p.hx[i]), scaled(p.hy[i]));
      });
    case Resampling::Average:
      return fill(0, [&](size_t i, int b, double x, double y) {
        return average(w, b, x, y, scaled(p.hx[i]), scaled(p.hy[i]));
      });
  }
}

}  // namespace maquette
