#include "gdal/resample_kernels.h"

#include <cmath>

namespace maquette::resample_detail {
namespace {

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

}  // namespace

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

}  // namespace maquette::resample_detail
