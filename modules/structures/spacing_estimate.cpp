#include "spacing_estimate.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>
#include <string>
#include <unsupported/Eigen/FFT>

namespace maquette::structures {
namespace {

int power_of_two_at_least(int n) {
  int p = 1;
  while (p < n) p *= 2;
  return p;
}

double hann(int k, int n) { return 0.5 - 0.5 * std::cos(2 * std::numbers::pi * (k + 0.5) / n); }

}  // namespace

double PixelAxes::area_side() const {
  return std::sqrt(std::abs(col_east * row_north - col_north * row_east));
}

RingPower ring_power(const std::vector<float>& image, int width, int height,
                     const PixelAxes& axes) {
  // A frequency (fx, fy) in cycles per pixel step is A^-T (fx, fy) in cycles per metre, A the
  // axes' matrix [col_east row_east; col_north row_north]; rings count it in cycles per
  // n x area_side metres.
  const double det = axes.col_east * axes.row_north - axes.col_north * axes.row_east;
  const double side_m = axes.area_side();
  double sum = 0;
  size_t finite = 0;
  for (const float v : image)
    if (std::isfinite(v)) sum += v, ++finite;
  const double mean = sum / double(finite);
  const int n = power_of_two_at_least(std::max(width, height));
  const auto side = static_cast<size_t>(n);
  // Rows of the padded image, transformed, then columns.
  using Complex = std::complex<double>;
  std::vector<std::vector<Complex>> rows(side, std::vector<Complex>(side));
  Eigen::FFT<double> fft;
  std::vector<Complex> in(side), out;
  for (int r = 0; r < height; ++r) {
    for (int c = 0; c < n; ++c) {
      const float v = c < width ? image[size_t(r) * size_t(width) + size_t(c)] : NAN;
      in[size_t(c)] = std::isfinite(v) ? (v - mean) * hann(c, width) * hann(r, height) : 0.0;
    }
    fft.fwd(rows[size_t(r)], in);
  }
  RingPower rings{n, std::vector<double>(side), std::vector<double>(side)};
  std::vector<Complex> column(side);
  for (int c = 0; c < n; ++c) {
    for (int r = 0; r < n; ++r) column[size_t(r)] = rows[size_t(r)][size_t(c)];
    fft.fwd(out, column);
    const double fx = double(c < n / 2 ? c : c - n);
    for (int r = 0; r < n; ++r) {
      const double fy = double(r < n / 2 ? r : r - n);
      const double east = (axes.row_north * fx - axes.col_north * fy) / det;
      const double north = (-axes.row_east * fx + axes.col_east * fy) / det;
      const auto ring = size_t(std::lround(std::hypot(east, north) * side_m));
      if (ring < side) rings.power[ring] += std::norm(out[size_t(r)]), rings.count[ring] += 1;
    }
  }
  return rings;
}

void add_rings(RingPower& a, const RingPower& b) {
  for (size_t k = 0; k < a.power.size(); ++k) a.power[k] += b.power[k], a.count[k] += b.count[k];
}

double spacing_from_rings(const RingPower& rings, double pixel_m) {
  if (rings.side < 16)
    throw std::runtime_error("images of " + std::to_string(rings.side) +
                             " pixels a side are too small to measure a spacing (16 at least)");
  std::vector<double> mean(rings.power.size());
  for (size_t k = 0; k < mean.size(); ++k) mean[k] = rings.power[k] / std::max(rings.count[k], 1.0);
  // Rings of spacings from a quarter of the side (4 cycles) down to 2.5 pixels.
  const size_t lo = 4, hi = size_t(0.4 * rings.side);
  const size_t peak =
      size_t(std::max_element(mean.begin() + lo, mean.begin() + hi + 1) - mean.begin());
  if (!(mean[peak] > 0)) throw std::runtime_error("the image is uniform: no crown to measure");
  const double a = mean[peak - 1], b = mean[peak], c = mean[peak + 1];
  if (peak == lo || peak == hi || !(b > a && b > c))
    throw std::runtime_error(
        "the spectrum has no peak between spacings of " + std::to_string(rings.side / 4) +
        " and 2.5 pixels (highest at " + std::to_string(peak) +
        " cycles per image, an end of that range): " + "no crowns at a regular spacing to measure");
  const double offset = (a - c) / (2 * (a - 2 * b + c));  // the parabola's vertex, in (-0.5, 0.5)
  return pixel_m * rings.side / (double(peak) + offset);
}

double estimate_spacing(const std::vector<float>& image, int width, int height, double pixel_m) {
  return spacing_from_rings(ring_power(image, width, height), pixel_m);
}

}  // namespace maquette::structures
