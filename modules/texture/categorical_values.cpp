#include "categorical_values.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "core/error.h"
#include "field.h"

namespace maquette::texture {

CategoricalSplit split_categorical(const Model& model) {
  CategoricalSplit out;
  int q = -1;
  for (size_t i = 0; i < model.quantities.size(); ++i)
    if (is_categorical(model.quantities[i].name)) q = int(i);
  out.model = model;
  if (q < 0) return out;
  Model& m = out.model;
  m.quantities.erase(m.quantities.begin() + q);
  for (Layer& l : m.layers) l.constraints.erase(l.constraints.begin() + q);
  Table identity;  // exp of the bin centre's log value
  for (int i = 0; i < kBins; ++i)
    identity[size_t(i)] = float(std::exp(kLogFloor * (1 - double(i) / (kBins - 1))));
  const size_t first = m.quantities.size();
  for (size_t l = 0; l < model.layers.size(); ++l) {
    const std::optional<Table>& t = model.layers[l].constraints[size_t(q)];
    if (!t) continue;
    m.quantities.push_back({model.quantities[size_t(q)].name + "/" + std::to_string(l),
                            kLogFloor * (1 + 0.5 / (kBins - 1)), -kLogFloor * 0.5 / (kBins - 1)});
    out.tables.push_back(*t);
    out.source.push_back(model.quantities[size_t(q)].name);
  }
  for (Layer& l : m.layers) l.constraints.resize(m.quantities.size());
  for (size_t k = 0, l = 0; l < model.layers.size(); ++l)
    if (model.layers[l].constraints[size_t(q)]) m.layers[l].constraints[first + k++] = identity;
  return out;
}

Tile<float> categorical_values(const Tile<float>& codes, const Table& table) {
  const int halo = codes.halo() - kPrefilterReach, n = codes.size();
  if (halo < kInputHalo)
    throw Error("texture: categorical input tiles need a halo of " +
                std::to_string(kInputHalo + kPrefilterReach) + " pixels");
  // The exact inverse of the B-spline's (1, 4, 1) / 6 is sqrt(3) z^|k|, z = sqrt(3) - 2;
  // truncated at |k| = kPrefilterReach (|z|^4 = 0.005) and renormalised to sum 1.
  std::array<double, 2 * kPrefilterReach + 1> w{};
  double sum = 0;
  for (int k = -kPrefilterReach; k <= kPrefilterReach; ++k)
    sum += w[size_t(k + kPrefilterReach)] =
        std::sqrt(3.0) * std::pow(std::sqrt(3.0) - 2, std::abs(k));
  for (double& v : w) v /= sum;
  const int wide = n + 2 * codes.halo();
  std::vector<double> value(size_t(wide) * size_t(wide)), rows(value.size());
  const auto at = [&](std::vector<double>& p, int c, int r) -> double& {
    return p[size_t(r + codes.halo()) * size_t(wide) + size_t(c + codes.halo())];
  };
  for (int r = -codes.halo(); r < n + codes.halo(); ++r)
    for (int c = -codes.halo(); c < n + codes.halo(); ++c) {
      const float code = codes.at(c, r);
      const float v = table[size_t(std::clamp(int(std::lround(code)), 0, kBins - 1))];
      at(value, c, r) = std::isnan(code) ? NAN : std::max(std::log(double(v)), kLogFloor);
    }
  for (int r = -codes.halo(); r < n + codes.halo(); ++r)
    for (int c = -halo; c < n + halo; ++c) {
      double v = 0;
      for (int k = -kPrefilterReach; k <= kPrefilterReach; ++k)
        v += w[size_t(k + kPrefilterReach)] * at(value, c + k, r);
      at(rows, c, r) = v;
    }
  Tile<float> out(n, 1, halo);
  for (int r = -halo; r < n + halo; ++r)
    for (int c = -halo; c < n + halo; ++c) {
      double v = 0;
      for (int k = -kPrefilterReach; k <= kPrefilterReach; ++k)
        v += w[size_t(k + kPrefilterReach)] * at(rows, c, r + k);
      out.at(c, r) = float(v);
    }
  return out;
}

}  // namespace maquette::texture
