#include "surface.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "lattice_noise.h"

namespace maquette::texture {

float table_coordinate(float unit) {
  return std::isnan(unit) ? float(kBins) : std::clamp(unit * kBins - 0.5f, 0.0f, float(kBins - 1));
}

PaddedTable padded(const Table& t) {
  PaddedTable p{};  // the two zeros at the end
  std::copy(t.begin(), t.end(), p.begin());
  return p;
}

Surface evaluate(const Model& model, const SurfaceInputs& in) {
  constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
  const size_t side = size_t(in.height.side()), layers = model.layers.size();
  Surface out{std::vector<float>(3 * in.height.v.size(), kNaN),
              Plane(in.height.size, in.height.ring, kNaN),
              Plane(in.height.size, in.height.ring, kNaN)};
  const int height_q = model.quantity("height"), slope_q = model.quantity("slope");
  std::vector<int> classes(layers);
  std::vector<float> scale(model.quantities.size()), offset(model.quantities.size());
  std::vector<std::vector<PaddedTable>> tables(layers);
  for (size_t l = 0; l < layers; ++l) {
    classes[l] = layer_class(model, int(l));
    for (const std::optional<Table>& t : model.layers[l].constraints)
      tables[l].push_back(t ? padded(*t) : PaddedTable{});
  }
  for (size_t q = 0; q < model.quantities.size(); ++q) {
    scale[q] = float(1 / (model.quantities[q].hi - model.quantities[q].lo));
    offset[q] = float(-model.quantities[q].lo) * scale[q];
  }
  const NoiseGeometry geometry{in.height.size, in.height.ring, in.col0,
                               in.row0,        in.pixel_m,     in.position};
  std::vector<NoiseField> fields;
  fields.reserve(layers);  // the lattices keep references
  std::vector<std::optional<LatticeNoise>> noise(layers);
  for (size_t l = 0; l < layers; ++l) {
    const Layer& layer = model.layers[l];
    fields.emplace_back(layer.noise);
    if (layer.noise_scale != 0 || layer.roughness_m != 0) noise[l].emplace(fields[l], geometry);
  }

  // One row of the planes at a time: per pixel, the layers in depth-first order. Each layer keeps
  // the list of pixels it covers, which its children start from (a layer cannot contribute more
  // than its parent); coverage is only defined on those pixels.
  std::vector<double> h(side);
  std::vector<float> rgb(3 * side), coverage(layers * side), product(side), n_x(side);
  std::vector<int> dominant(side);
  std::vector<uint32_t> valid(side), lists(layers * side);
  std::vector<size_t> listed(layers);
  // Per quantity: its table coordinates along the row, shared by the layers (the displaced
  // height's filled in by each layer that reads it).
  std::vector<std::vector<float>> coordinate(model.quantities.size(), std::vector<float>(side));
  for (size_t r = 0; r < side; ++r) {
    const size_t row = r * side;
    for (size_t q = 0; q < coordinate.size(); ++q) {
      if (int(q) == height_q) continue;
      const float* plane =
          (int(q) == slope_q ? in.slope.v.data() : in.quantities[q]->v.data()) + row;
      for (size_t c = 0; c < side; ++c)
        coordinate[q][c] = table_coordinate(plane[c] * scale[q] + offset[q]);
    }
    size_t n_valid = 0;
    for (size_t c = 0; c < side; ++c) {
      h[c] = in.height.v[row + c];
      valid[n_valid] = uint32_t(c);
      n_valid += !std::isnan(h[c]);  // a missing height has no layers
    }
    std::fill(rgb.begin(), rgb.end(), 0.0f);
    std::fill(dominant.begin(), dominant.end(), -1);
    for (size_t l = 0; l < layers; ++l) {
      const Layer& layer = model.layers[l];
      float* cov = &coverage[l * side];
      uint32_t* active = &lists[l * side];
      // The pixels the layer can contribute to: those its parent covers, then those where every
      // constraint is > 0.
      size_t n = 0;
      const float* parent = layer.parent < 0 ? nullptr : &coverage[size_t(layer.parent) * side];
      if (!parent) {
        std::copy(valid.begin(), valid.begin() + ptrdiff_t(n_valid), active);
        n = n_valid;
        for (size_t k = 0; k < n; ++k) product[active[k]] = 1;
      } else {
        const uint32_t* from = &lists[size_t(layer.parent) * side];
        for (size_t k = 0; k < listed[size_t(layer.parent)]; ++k) {
          active[n] = from[k];
          product[from[k]] = 1;
          n += parent[from[k]] > 0;
        }
      }
      for (size_t q = 0; q < layer.constraints.size() && n > 0; ++q) {
        if (!layer.constraints[q]) continue;
        const PaddedTable& table = tables[l][q];
        float* x = coordinate[q].data();
        if (int(q) == height_q)  // the displaced height, where the layer is still active
          for (size_t k = 0; k < n; ++k)
            x[active[k]] = table_coordinate(float(h[active[k]]) * scale[q] + offset[q]);
        size_t kept = 0;
        for (size_t k = 0; k < n; ++k) {
          const uint32_t c = active[k];
          const float p = product[c] * lookup_at(table, x[c]);
          product[c] = p;
          active[kept] = c;
          kept += p > 0;
        }
        n = kept;
      }
      listed[l] = n;
      if (noise[l])  // over each run of consecutive pixels
        for (size_t k = 0; k < n;) {
          const size_t first = k;
          while (k + 1 < n && active[k + 1] == active[k] + 1) ++k;
          const int ring = in.height.ring;
          noise[l]->row(int(r) - ring, int(active[first]) - ring, int(active[k]) - ring,
                        n_x.data() + active[first]);
          ++k;
        }
      for (size_t k = 0; k < n; ++k) {
        const uint32_t c = active[k];
        const float nx = noise[l] ? n_x[c] : 0.0f;
        const float cv =
            std::clamp((layer.bias + layer.noise_scale * nx) * product[c], 0.0f, 1.0f) *
            (parent ? parent[c] : 1.0f);
        cov[c] = cv;
        for (size_t i = 0; i < 3; ++i)
          rgb[3 * c + i] = (1 - cv) * rgb[3 * c + i] + cv * layer.colour[i];
        h[c] += double(cv * layer.roughness_m * nx);
        if (cv >= 0.5f) dominant[c] = int(l);
      }
    }
    for (size_t c = 0; c < side; ++c) {
      const size_t p = row + c;
      if (std::isnan(in.height.v[p])) continue;
      for (size_t k = 0; k < 3; ++k) out.rgb[3 * p + k] = rgb[3 * c + k];
      out.height.v[p] = float(h[c]);
      if (dominant[c] >= 0 && classes[size_t(dominant[c])] >= 0)
        out.dominant_class.v[p] = float(classes[size_t(dominant[c])]);
    }
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
