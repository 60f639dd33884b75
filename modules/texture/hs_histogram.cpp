#include "hs_histogram.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "hs_classes.h"

namespace maquette::texture {

ColourSpace parse_colour_space(const std::string& name) {
  if (name == "hs") return ColourSpace::Hs;
  if (name == "hsv") return ColourSpace::Hsv;
  if (name == "lab") return ColourSpace::Lab;
  throw Error("unknown colour space '" + name + "' (expected hs, hsv or lab)");
}

int histogram_dims(ColourSpace space) { return space == ColourSpace::Hs ? 2 : 3; }

int histogram_bins(ColourSpace space) {
  if (space == ColourSpace::Lab) return kLightnessBins * kChromaBins * kChromaBins;
  return kHueBins * kSatBins * (space == ColourSpace::Hs ? 1 : kValueBins);
}

int lab_bin(const Lab& lab) {
  const int l = std::clamp(int(lab[0] / 100 * kLightnessBins), 0, kLightnessBins - 1);
  const auto chroma = [](double x) {
    return std::clamp(int(std::floor((x + kChromaLimit) / (2 * kChromaLimit) * kChromaBins)), 0,
                      kChromaBins - 1);
  };
  return (l * kChromaBins + chroma(lab[1])) * kChromaBins + chroma(lab[2]);
}

Lab point_lab(const Point& p) { return {p[2] / kLabLightnessWeight * 100, p[0] * 100, p[1] * 100}; }

Point lab_point(const Lab& lab) {
  return {lab[1] / 100, lab[2] / 100, kLabLightnessWeight * lab[0] / 100};
}

int colour_bin(const Hsv& x, ColourSpace space) {
  const int h = std::clamp(int(x.h / 360 * kHueBins), 0, kHueBins - 1);
  const int s = std::clamp(int(x.s * kSatBins), 0, kSatBins - 1);
  if (space == ColourSpace::Hs) return h * kSatBins + s;
  const int v = std::clamp(int(x.v * kValueBins), 0, kValueBins - 1);
  return (h * kSatBins + s) * kValueBins + v;
}

std::vector<uint64_t> hs_marginal(const std::vector<uint64_t>& histogram, ColourSpace space) {
  if (space == ColourSpace::Lab) throw Error("no hue-saturation marginal of a CIELAB histogram");
  const size_t per_hs = space == ColourSpace::Hs ? 1 : kValueBins;
  std::vector<uint64_t> out(size_t(kHueBins * kSatBins), 0);
  for (size_t i = 0; i < histogram.size(); ++i) out[i / per_hs] += histogram[i];
  return out;
}

namespace {

BinPoint lab_bin_point(size_t i, uint64_t count) {
  const double dl = 100.0 / kLightnessBins, dc = 2 * kChromaLimit / kChromaBins;
  const int b = int(i) % kChromaBins, a = int(i) / kChromaBins % kChromaBins,
            l = int(i) / (kChromaBins * kChromaBins);
  const Point x =
      lab_point({(l + 0.5) * dl, (a + 0.5) * dc - kChromaLimit, (b + 0.5) * dc - kChromaLimit});
  const double sc = dc / 100, sl = kLabLightnessWeight * dl / 100;
  const Matrix spread = {{{sc * sc / 12, 0, 0}, {0, sc * sc / 12, 0}, {0, 0, sl * sl / 12}}};
  return {x, double(count), spread, sc * sc * sl};
}

BinPoint bin_point(size_t i, ColourSpace space, uint64_t count) {
  if (space == ColourSpace::Lab) return lab_bin_point(i, count);
  const bool hsv = space == ColourSpace::Hsv;
  const int hs = int(i) / (hsv ? kValueBins : 1);
  const double hue = (hs / kSatBins + 0.5) * 360.0 / kHueBins;
  const double s = (hs % kSatBins + 0.5) / kSatBins, ds = 1.0 / kSatBins;
  const double dv = hsv ? 1.0 / kValueBins : 1;
  const auto xy = wheel(hue, s);
  const double v = hsv ? (int(i) % kValueBins + 0.5) * dv : 0;
  const double c = std::cos(hue * M_PI / 180), n = std::sin(hue * M_PI / 180);
  const double radial = ds * ds / 12, along = std::pow(s * 2 * M_PI / kHueBins, 2) / 12;
  const Matrix spread = {{{radial * c * c + along * n * n, (radial - along) * c * n, 0},
                          {(radial - along) * c * n, radial * n * n + along * c * c, 0},
                          {0, 0, hsv ? dv * dv / 12 : 0}}};
  return {{xy[0], xy[1], v}, double(count), spread, s * ds * 2 * M_PI / kHueBins * dv};
}

}  // namespace

std::vector<BinPoint> occupied_bins(const std::vector<uint64_t>& histogram, ColourSpace space) {
  std::vector<BinPoint> out;
  for (size_t i = 0; i < histogram.size(); ++i)
    if (histogram[i] > 0) out.push_back(bin_point(i, space, histogram[i]));
  return out;
}

std::vector<BinPoint> all_bins(ColourSpace space) {
  std::vector<BinPoint> out;
  for (size_t i = 0; i < size_t(histogram_bins(space)); ++i) out.push_back(bin_point(i, space, 0));
  return out;
}

Hsv point_colour(const Point& p) {
  const double hue = std::atan2(p[1], p[0]) * 180 / M_PI;
  return {hue < 0 ? std::fmod(hue + 360, 360) : hue, std::hypot(p[0], p[1]), p[2]};
}

double squared_distance(const Point& a, const Point& b) {
  return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
         (a[2] - b[2]) * (a[2] - b[2]);
}

}  // namespace maquette::texture
