#include "light_guide.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "../texture/colour.h"

namespace maquette::synthesis {

std::vector<float> class_quantiles(const std::vector<float>& values,
                                   const std::vector<uint8_t>& classes,
                                   const std::vector<uint8_t>& counted) {
  std::array<std::vector<float>, 256> sorted;
  for (size_t i = 0; i < values.size(); ++i)
    if (counted[i] && !std::isnan(values[i])) sorted[classes[i]].push_back(values[i]);
  for (auto& v : sorted) std::sort(v.begin(), v.end());
  std::vector<float> out(values.size(), std::numeric_limits<float>::quiet_NaN());
  for (size_t i = 0; i < values.size(); ++i) {
    const std::vector<float>& v = sorted[classes[i]];
    if (v.empty() || std::isnan(values[i])) continue;
    const auto [low, high] = std::equal_range(v.begin(), v.end(), values[i]);
    const double below = double(low - v.begin()), equal = double(high - low);
    out[i] = float((below + 0.5 * equal) / double(v.size()));
  }
  return out;
}

std::vector<float> painting_light(const Exemplar& e, const std::vector<float>& values) {
  std::vector<uint8_t> allowed(e.labels.size());
  for (size_t i = 0; i < allowed.size(); ++i) allowed[i] = !e.excluded[i];
  std::vector<float> out = class_quantiles(values, e.labels, allowed);
  for (float& v : out)
    if (std::isnan(v)) v = 0.5f;
  return out;
}

std::vector<float> painting_lightness(const Exemplar& e) {
  std::vector<float> lightness(e.labels.size());
  for (size_t i = 0; i < lightness.size(); ++i) {
    const float* rgb = &e.rgb[3 * i];
    lightness[i] = float(texture::srgb_to_lab(rgb[0], rgb[1], rgb[2])[0]);
  }
  return lightness;
}

}  // namespace maquette::synthesis
