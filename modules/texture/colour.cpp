#include "colour.h"

#include <algorithm>
#include <cmath>

#include "core/srgb.h"

namespace maquette::texture {
namespace {

constexpr double kDeg = 180 / M_PI;

double linear(double c) { return srgb_to_linear(c / 255); }

double lab_f(double t) { return t > 216.0 / 24389 ? std::cbrt(t) : (24389.0 / 27 * t + 16) / 116; }

// lab_f's inverse (its two pieces meet at f = 6 / 29, t = 216 / 24389).
double lab_f_inverse(double f) { return f > 6.0 / 29 ? f * f * f : (116 * f - 16) * 27 / 24389; }

}  // namespace

Hsv rgb_to_hsv(double r, double g, double b) {
  const double mx = std::max({r, g, b}), mn = std::min({r, g, b}), d = mx - mn;
  Hsv out{0, mx > 0 ? d / mx : 0, mx / 255};
  if (d <= 0) return out;
  double h = mx == r ? (g - b) / d : mx == g ? 2 + (b - r) / d : 4 + (r - g) / d;
  h *= 60;
  out.h = h < 0 ? h + 360 : h;
  return out;
}

std::array<double, 3> srgb_to_lab(double r, double g, double b) {
  const double R = linear(r), G = linear(g), B = linear(b);
  const double x = (0.4124564 * R + 0.3575761 * G + 0.1804375 * B) / 0.95047;
  const double y = 0.2126729 * R + 0.7151522 * G + 0.0721750 * B;
  const double z = (0.0193339 * R + 0.1191920 * G + 0.9503041 * B) / 1.08883;
  const double fx = lab_f(x), fy = lab_f(y), fz = lab_f(z);
  return {116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)};
}

std::array<double, 3> lab_to_srgb(const Lab& lab) {
  const double fy = (lab[0] + 16) / 116, fx = fy + lab[1] / 500, fz = fy - lab[2] / 200;
  const double x = lab_f_inverse(fx) * 0.95047, y = lab_f_inverse(fy),
               z = lab_f_inverse(fz) * 1.08883;
  return {srgb_from_linear(3.2404542 * x - 1.5371385 * y - 0.4985314 * z),
          srgb_from_linear(-0.9692660 * x + 1.8760108 * y + 0.0415560 * z),
          srgb_from_linear(0.0556434 * x - 0.2040259 * y + 1.0572252 * z)};
}

double ciede2000(const std::array<double, 3>& p, const std::array<double, 3>& q) {
  const double c1 = std::hypot(p[1], p[2]), c2 = std::hypot(q[1], q[2]);
  const double cm = (c1 + c2) / 2, cm7 = std::pow(cm, 7);
  const double g = 0.5 * (1 - std::sqrt(cm7 / (cm7 + std::pow(25.0, 7))));
  const double a1 = (1 + g) * p[1], a2 = (1 + g) * q[1];
  const double C1 = std::hypot(a1, p[2]), C2 = std::hypot(a2, q[2]);
  const auto hue = [](double b, double a) {
    if (a == 0 && b == 0) return 0.0;
    const double h = std::atan2(b, a) * kDeg;
    return h < 0 ? h + 360 : h;
  };
  const double h1 = hue(p[2], a1), h2 = hue(q[2], a2);
  const double dL = q[0] - p[0], dC = C2 - C1;
  double dh = 0;
  if (C1 * C2 != 0) {
    dh = h2 - h1;
    if (dh > 180) dh -= 360;
    if (dh < -180) dh += 360;
  }
  const double dH = 2 * std::sqrt(C1 * C2) * std::sin(dh / 2 / kDeg);
  const double Lm = (p[0] + q[0]) / 2, Cm = (C1 + C2) / 2;
  double hm = h1 + h2;
  if (C1 * C2 != 0) {
    if (std::abs(h1 - h2) <= 180)
      hm = (h1 + h2) / 2;
    else
      hm = h1 + h2 < 360 ? (h1 + h2 + 360) / 2 : (h1 + h2 - 360) / 2;
  }
  const double t = 1 - 0.17 * std::cos((hm - 30) / kDeg) + 0.24 * std::cos(2 * hm / kDeg) +
                   0.32 * std::cos((3 * hm + 6) / kDeg) - 0.20 * std::cos((4 * hm - 63) / kDeg);
  const double dTheta = 30 * std::exp(-std::pow((hm - 275) / 25, 2));
  const double Cm7 = std::pow(Cm, 7);
  const double rc = 2 * std::sqrt(Cm7 / (Cm7 + std::pow(25.0, 7)));
  const double sl = 1 + 0.015 * (Lm - 50) * (Lm - 50) / std::sqrt(20 + (Lm - 50) * (Lm - 50));
  const double sc = 1 + 0.045 * Cm, sh = 1 + 0.015 * Cm * t;
  const double rt = -std::sin(2 * dTheta / kDeg) * rc;
  const double l = dL / sl, c = dC / sc, h = dH / sh;
  return std::sqrt(l * l + c * c + h * h + rt * c * h);
}

}  // namespace maquette::texture
