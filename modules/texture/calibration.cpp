#include "calibration.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace maquette::texture {

void calibrate_biases(Model& model, const std::vector<Sample>& samples) {
  std::vector<size_t> level1;
  for (size_t l = 0; l < model.layers.size(); ++l)
    if (model.layers[l].parent == 0) level1.push_back(l);
  std::vector<bool> taken(samples.size(), false);
  for (size_t i = level1.size(); i-- > 1;) {
    Layer& layer = model.layers[level1[i]];
    uint64_t observed = 0;
    std::vector<float> products(samples.size(), 0);
    std::vector<float> free;  // products of the samples no later layer dominates
    for (size_t s = 0; s < samples.size(); ++s) {
      if (samples[s].class_id == layer.class_id) ++observed;
      float p = 1;
      for (size_t q = 0; q < layer.constraints.size(); ++q)
        if (layer.constraints[q]) p *= (*layer.constraints[q])[samples[s].bins[q]];
      products[s] = p;
      if (!taken[s] && p > 0) free.push_back(p);
    }
    if (observed == 0 || free.empty()) continue;
    // The threshold admitting `observed` free samples: the observed-th largest product.
    const size_t k = std::min<size_t>(observed, free.size()) - 1;
    std::nth_element(free.begin(), free.begin() + std::ptrdiff_t(k), free.end(), std::greater<>());
    layer.bias = std::min(kMaxBias, 0.5f / free[k]);
    for (size_t s = 0; s < samples.size(); ++s)
      if (layer.bias * products[s] >= 0.5f) taken[s] = true;
  }
}

void sharpen_coverage(Model& model, double power) {
  for (Layer& layer : model.layers) {
    if (layer.parent != 0 ||
        std::none_of(layer.constraints.begin(), layer.constraints.end(),
                     [](const std::optional<Table>& t) { return t.has_value(); }))
      continue;
    // The power is lowered where the bias would pass kMaxSharpenedBias (float's range).
    const double b = 2.0 * layer.bias;
    const double p = b > 1 ? std::min(power, std::log(2 * kMaxSharpenedBias) / std::log(b)) : power;
    for (std::optional<Table>& t : layer.constraints)
      if (t)
        for (float& v : *t) v = float(std::pow(double(v), p));
    layer.bias = float(0.5 * std::pow(b, p));
  }
}

}  // namespace maquette::texture
