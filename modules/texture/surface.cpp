#include "surface.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "core/avx2_clones.h"
#include "lattice_noise.h"
#include "layer_kernels.h"

namespace maquette::texture {

PaddedTable padded(const Table& t) {
  PaddedTable p{};  // the two zeros at the end
  std::copy(t.begin(), t.end(), p.begin());
  return p;
}

// The loops around the kernels vectorized for AVX2 where the CPU has it (the same bits).
MAQUETTE_AVX2_CLONES void evaluate(const Model& model, const SurfaceInputs& in,
                                   const SurfaceTargets& out) {
  constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
  const size_t side = size_t(in.height.side()), layers = model.layers.size();
  // The rows and columns of the planes in the rgb and classes targets.
  const size_t first = size_t(in.height.ring - out.ring), out_side = side - 2 * first;
  const int height_q = model.quantity("height"), slope_q = model.quantity("slope");
  std::vector<int> class_of(layers);  // -1: none (NaN in the classes target)
  std::vector<float> scale(model.quantities.size()), offset(model.quantities.size());
  std::vector<std::vector<PairTable>> tables(layers);
  for (size_t l = 0; l < layers; ++l) {
    class_of[l] = layer_class(model, int(l));
    for (const std::optional<Table>& t : model.layers[l].constraints)
      tables[l].push_back(t ? pair_table(padded(*t)) : PairTable{});
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

  // One row of the planes at a time, layer by layer over blocks of 8 pixels (layer_kernels.h).
  // Each layer keeps the list of blocks it covers, which its children start from (a layer cannot
  // contribute more than its parent); coverage is only defined in those blocks.
  const LayerKernels& kernels = fastest_kernels();
  const size_t blocks = (side + kBlock - 1) / kBlock, padded_side = blocks * kBlock;
  std::vector<float> h(padded_side, kNaN);  // the padding is a missing height
  std::vector<float> valid(padded_side), rgb(3 * padded_side), coverage(layers * padded_side),
      product(padded_side), n_x(padded_side);
  std::vector<int> dominant(padded_side);  // the dominant layer's class (-1: none)
  std::vector<uint16_t> every_block(blocks), lists(layers * blocks);
  for (size_t b = 0; b < blocks; ++b) every_block[b] = uint16_t(b);
  std::vector<size_t> listed(layers);
  // Per quantity: its table coordinates along the row, shared by the layers (those of the
  // displaced height computed by the layers that read it).
  std::vector<std::vector<float>> coordinate(model.quantities.size(),
                                             std::vector<float>(padded_side, float(kBins)));
  // A constraint that is 1 over all the coordinates of a row multiplies by exactly 1 there: it is
  // skipped for that row (hats over most of a quantity's range often are). For each bin i,
  // ones_until[i] is the last bin j >= i with bins i .. j of the padded table 1 (i - 1: none).
  struct LayerConstraint {
    size_t q;
    std::array<int, kBins + 2> ones_until;
  };
  std::vector<std::vector<LayerConstraint>> layer_constraints(layers);
  for (size_t l = 0; l < layers; ++l)
    for (size_t q = 0; q < model.layers[l].constraints.size(); ++q)
      if (const std::optional<Table>& t = model.layers[l].constraints[q]) {
        LayerConstraint& lc = layer_constraints[l].emplace_back(LayerConstraint{q, {}});
        const PaddedTable p = padded(*t);
        for (int i = kBins + 1; i >= 0; --i)
          lc.ones_until[size_t(i)] = p[size_t(i)] != 1 ? i - 1
                                     : i == kBins + 1  ? i
                                                       : lc.ones_until[size_t(i) + 1];
      }
  std::vector<int> lowest(model.quantities.size()), highest(model.quantities.size());
  std::vector<ConstraintRow> constraints;  // of the layer along the row
  constraints.reserve(model.quantities.size());
  const int ring = in.height.ring;
  for (size_t r = 0; r < side; ++r) {
    const size_t row = r * side;
    for (size_t q = 0; q < coordinate.size(); ++q) {
      if (int(q) == height_q) continue;
      kernels.coordinates(
          (int(q) == slope_q ? in.slope.v.data() : in.quantities[q]->v.data()) + row, side,
          scale[q], offset[q], coordinate[q].data());
      int lo = kBins, hi = 0;  // the bins the row's pixels read
      for (size_t c = 0; c < side; ++c) {
        const int i = int(coordinate[q][c]);
        lo = std::min(lo, i);
        hi = std::max(hi, i);
      }
      lowest[q] = lo, highest[q] = hi;
    }
    for (size_t c = 0; c < side; ++c) {
      h[c] = in.height.v[row + c];
      valid[c] = std::isnan(h[c]) ? 0.0f : 1.0f;  // a missing height has no layers
    }
    for (size_t k = 0; k < 3; ++k)  // black, NaN where missing (no layer blends there)
      for (size_t c = 0; c < padded_side; ++c)
        rgb[k * padded_side + c] = valid[c] > 0 ? 0.0f : kNaN;
    std::fill(dominant.begin(), dominant.end(), -1);
    for (size_t l = 0; l < layers; ++l) {
      const Layer& layer = model.layers[l];
      const bool root = layer.parent < 0;
      const float* parent = root ? valid.data() : &coverage[size_t(layer.parent) * padded_side];
      uint16_t* active = &lists[l * blocks];
      constraints.clear();
      for (const LayerConstraint& lc : layer_constraints[l]) {
        const bool height = int(lc.q) == height_q;
        if (!height && lc.ones_until[size_t(lowest[lc.q])] >= highest[lc.q] + 1) continue;
        constraints.push_back({tables[l][lc.q].data(), height ? nullptr : coordinate[lc.q].data()});
      }
      const size_t n = kernels.constrain(
          {parent, constraints, h.data(), height_q < 0 ? 1 : scale[size_t(height_q)],
           height_q < 0 ? 0 : offset[size_t(height_q)], product.data()},
          root ? every_block.data() : &lists[size_t(layer.parent) * blocks],
          root ? blocks : listed[size_t(layer.parent)], active);
      listed[l] = n;
      if (noise[l])  // over each run of consecutive blocks
        for (size_t k = 0; k < n;) {
          const size_t first = k;
          while (k + 1 < n && active[k + 1] == active[k] + 1) ++k;
          const size_t c0 = size_t(active[first]) * kBlock,
                       c1 = std::min(size_t(active[k]) * kBlock + kBlock, side) - 1;
          noise[l]->row(int(r) - ring, int(c0) - ring, int(c1) - ring, n_x.data() + c0);
          ++k;
        }
      kernels.blend({layer.bias,
                     layer.noise_scale,
                     layer.roughness_m,
                     layer.colour,
                     class_of[l],
                     parent,
                     product.data(),
                     noise[l] ? n_x.data() : nullptr,
                     &coverage[l * padded_side],
                     {&rgb[0], &rgb[padded_side], &rgb[2 * padded_side]},
                     h.data(),
                     dominant.data()},
                    active, n);
    }
    for (size_t c = 0; c < side; ++c) out.height[row + c] = valid[c] > 0 ? h[c] : kNaN;
    if (r < first || r >= first + out_side) continue;
    const size_t out_row = (r - first) * out_side;
    if (out.rgb)
      for (size_t c = 0; c < out_side; ++c)
        for (size_t k = 0; k < 3; ++k)
          out.rgb[3 * (out_row + c) + k] = rgb[k * padded_side + first + c];
    if (out.classes)
      for (size_t c = 0; c < out_side; ++c)
        out.classes[out_row + c] = dominant[first + c] < 0 ? kNaN : float(dominant[first + c]);
  }
}

Surface evaluate(const Model& model, const SurfaceInputs& in) {
  Surface s{std::vector<float>(3 * in.height.v.size()), Plane(in.height.size, in.height.ring),
            Plane(in.height.size, in.height.ring)};
  evaluate(model, in, {in.height.ring, s.rgb.data(), s.dominant_class.v.data(), s.height.v.data()});
  return s;
}

// In float, vectorized for AVX2 where the CPU has it (the same operations, so the same bits; the
// sqrt vectorizes since this file does not set errno, CMakeLists.txt).
MAQUETTE_AVX2_CLONES void normals(const Plane& h, double pixel_m, float* out) {
  const float k = float(1 / (2 * pixel_m));
  const size_t m = size_t(h.size);
  for (int r = 0; r < h.size; ++r) {
    const size_t side = size_t(h.side());
    const float* mid = &h.v[size_t(r + h.ring) * side + size_t(h.ring)];
    const float *up = mid - side, *down = mid + side, *left = mid - 1, *right = mid + 1;
    float* o = out + size_t(r) * m * 3;
    for (size_t c = 0; c < m; ++c) {
      const float gx = (right[c] - left[c]) * k;
      const float gy = (up[c] - down[c]) * k;  // rows grow downwards
      const float inverse_norm = 1 / std::sqrt(gx * gx + gy * gy + 1);
      o[3 * c] = -gx * inverse_norm, o[3 * c + 1] = -gy * inverse_norm, o[3 * c + 2] = inverse_norm;
    }
  }
}

}  // namespace maquette::texture
