#include "surface.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace maquette::texture {

float lookup(const Table& t, float unit) {
  const float x = std::clamp(unit * kBins - 0.5f, 0.0f, float(kBins - 1));
  const int i = std::min(int(x), kBins - 2);
  const float f = x - float(i);
  return t[size_t(i)] + f * (t[size_t(i) + 1] - t[size_t(i)]);
}

Surface evaluate(const Model& model, const SurfaceInputs& in) {
  constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
  const size_t n = in.height.v.size(), layers = model.layers.size();
  Surface out{std::vector<float>(3 * n, kNaN), Plane(in.height.size, in.height.ring, kNaN),
              Plane(in.height.size, in.height.ring, kNaN)};
  const int height_q = model.quantity("height"), slope_q = model.quantity("slope");
  std::vector<int> classes(layers);
  std::vector<float> scale(model.quantities.size()), offset(model.quantities.size());
  for (size_t l = 0; l < layers; ++l) classes[l] = layer_class(model, int(l));
  for (size_t q = 0; q < model.quantities.size(); ++q) {
    scale[q] = float(1 / (model.quantities[q].hi - model.quantities[q].lo));
    offset[q] = float(-model.quantities[q].lo) * scale[q];
  }
  std::vector<NoiseField> noise;
  for (const Layer& l : model.layers) noise.emplace_back(l.noise);
  std::vector<float> coverage(layers);
  for (size_t p = 0; p < n; ++p) {
    double h = in.height.v[p];
    if (std::isnan(h)) continue;
    float rgb[3] = {0, 0, 0};
    int dominant = -1;
    for (size_t l = 0; l < layers; ++l) {
      const Layer& layer = model.layers[l];
      const float parent = layer.parent < 0 ? 1.0f : coverage[size_t(layer.parent)];
      coverage[l] = 0;
      if (parent <= 0) continue;  // a layer cannot contribute more than its parent
      float product = 1;
      for (size_t q = 0; q < layer.constraints.size() && product > 0; ++q) {
        if (!layer.constraints[q]) continue;
        const float v = int(q) == height_q  ? float(h)
                        : int(q) == slope_q ? in.slope.v[p]
                                            : in.quantities[q]->v[p];
        product *= std::isnan(v) ? 0.0f : lookup(*layer.constraints[q], v * scale[q] + offset[q]);
      }
      if (product <= 0) continue;
      const bool noisy = layer.noise_scale != 0 || layer.roughness_m != 0;
      const float n_x = noisy ? noise[l]((*in.position)[p]) : 0.0f;
      const float c =
          std::clamp((layer.bias + layer.noise_scale * n_x) * product, 0.0f, 1.0f) * parent;
      coverage[l] = c;
      for (int k = 0; k < 3; ++k) rgb[k] = (1 - c) * rgb[k] + c * layer.colour[size_t(k)];
      h += double(c * layer.roughness_m * n_x);
      if (c >= 0.5f) dominant = int(l);
    }
    for (int k = 0; k < 3; ++k) out.rgb[3 * p + size_t(k)] = rgb[k];
    out.height.v[p] = float(h);
    if (dominant >= 0 && classes[size_t(dominant)] >= 0)
      out.dominant_class.v[p] = float(classes[size_t(dominant)]);
  }
  return out;
}

std::vector<float> normals(const Plane& h, double pixel_m) {
  std::vector<float> out(size_t(h.size) * size_t(h.size) * 3);
  const double k = 1 / (2 * pixel_m);
  for (int r = 0; r < h.size; ++r)
    for (int c = 0; c < h.size; ++c) {
      const double gx = (h.at(c + 1, r) - h.at(c - 1, r)) * k;
      const double gy = (h.at(c, r - 1) - h.at(c, r + 1)) * k;  // rows grow downwards
      const double norm = std::sqrt(gx * gx + gy * gy + 1);
      float* o = &out[(size_t(r) * size_t(h.size) + size_t(c)) * 3];
      o[0] = float(-gx / norm), o[1] = float(-gy / norm), o[2] = float(1 / norm);
    }
  return out;
}

}  // namespace maquette::texture
