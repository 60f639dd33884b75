#include "hs_classes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"

namespace maquette::texture {
namespace {

bool in_range(double v, const std::array<double, 2>& r) { return v >= r[0] && v <= r[1]; }

bool in_hue(double h, const std::array<double, 2>& r) {
  return r[0] <= r[1] ? in_range(h, r) : (h >= r[0] || h <= r[1]);
}

std::array<double, 2> pair(const nlohmann::json& j, const char* key,
                           std::array<double, 2> fallback) {
  return j.contains(key) ? std::array<double, 2>{j[key][0].get<double>(), j[key][1].get<double>()}
                         : fallback;
}

}  // namespace

std::array<double, 2> wheel(double hue, double saturation) {
  const double a = hue * M_PI / 180;
  return {saturation * std::cos(a), saturation * std::sin(a)};
}

nlohmann::json grey_params_schema() {
  return {{"grey_threshold",
           {{"type", "number"},
            {"minimum", 0},
            {"maximum", 255},
            {"default", 10},
            {"description", "max(R,G,B) - min(R,G,B) at or below which a pixel is grey"}}},
          {"grey_hue",
           {{"type", "number"},
            {"minimum", 0},
            {"maximum", 360},
            {"default", 300},
            {"description", "hue given to grey pixels"}}}};
}

HsClassifier HsClassifier::from_params(const nlohmann::json& p) {
  HsClassifier c;
  c.grey_threshold = p.at("grey_threshold").get<double>();
  c.grey_hue = p.at("grey_hue").get<double>();
  for (const auto& b : p.value("boxes", nlohmann::json::array()))
    c.boxes.push_back({b.at("id").get<int>(), pair(b, "hue", {0, 360}),
                       pair(b, "saturation", {0, 1}), pair(b, "value", {0, 1})});
  for (const auto& z : p.value("centres", nlohmann::json::array()))
    c.centres.push_back({z.at("id").get<int>(), z.at("hue").get<double>(),
                         z.at("saturation").get<double>(), z.value("value", double(NAN))});
  for (const Centre& z : c.centres)
    if (std::isnan(z.value) != std::isnan(c.centres.front().value))
      throw Error("params.centres: give \"value\" for every centre or for none (centre id " +
                  std::to_string(z.id) + ")");
  return c;
}

Hsv HsClassifier::hsv(double r, double g, double b) const {
  Hsv x = rgb_to_hsv(r, g, b);
  if (std::max({r, g, b}) - std::min({r, g, b}) <= grey_threshold) x.h = grey_hue;
  return x;
}

int HsClassifier::classify(double r, double g, double b) const {
  const Hsv x = hsv(r, g, b);
  for (const Box& box : boxes)
    if (in_hue(x.h, box.hue) && in_range(x.s, box.saturation) && in_range(x.v, box.value))
      return box.id;
  int best = -1;
  double best_d = std::numeric_limits<double>::infinity();
  const auto p = wheel(x.h, x.s);
  for (const Centre& z : centres) {
    const auto q = wheel(z.hue, z.saturation);
    const double dv = std::isnan(z.value) ? 0 : x.v - z.value;
    const double d = std::hypot(p[0] - q[0], p[1] - q[1], dv);
    if (d < best_d) best_d = d, best = z.id;
  }
  return best;
}

}  // namespace maquette::texture
