#include "hierarchy.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace maquette::texture {
namespace {

// Deterministic uniform in [-1, 1] from (seed, a, b, c).
double jitter(uint64_t seed, uint64_t a, uint64_t b, uint64_t c) {
  uint64_t x = seed ^ (a * 0x9E3779B97F4A7C15ULL) ^ (b * 0xC2B2AE3D27D4EB4FULL) ^ (c + 1);
  x ^= x >> 30, x *= 0xbf58476d1ce4e5b9ULL, x ^= x >> 27, x *= 0x94d049bb133111ebULL, x ^= x >> 31;
  return double(x >> 11) / double(1ULL << 52) - 1;
}

std::array<float, 3> mean_colour(const ClassStats& c) {
  std::array<float, 3> m{};
  for (size_t k = 0; k < 3; ++k) m[k] = float(c.sum[k] / double(c.pixels));
  return m;
}

}  // namespace

Table constraint_function(const std::array<uint64_t, kBins>& hist) {
  const double total = double(std::accumulate(hist.begin(), hist.end(), uint64_t(0)));
  Table t{};
  if (total == 0) return t;
  const double k = 0.5 / (total / kBins);
  for (int i = 0; i < kBins; ++i) t[size_t(i)] = float(std::min(1.0, double(hist[size_t(i)]) * k));
  return t;
}

Table odds_function(const std::array<uint64_t, kBins>& hist,
                    const std::array<uint64_t, kBins>& all) {
  Table t{};
  double top = 0;
  std::array<double, kBins> o{};
  for (size_t i = 0; i < size_t(kBins); ++i)
    if (all[i] > 0) {
      o[i] = std::clamp((double(hist[i]) + 0.5) / (double(all[i] - hist[i]) + 0.5), 1.0 / 64, 64.0);
      top = std::max(top, o[i]);
    }
  if (top == 0) return t;
  // Bins without pixels take the odds of the nearest bin with pixels (the lower on a tie), so
  // values outside those fitted extrapolate the nearest behaviour seen instead of giving every
  // class 0, which hands them to the root's class.
  std::array<double, kBins> filled = o;
  for (int i = 0; i < kBins; ++i) {
    if (all[size_t(i)] > 0) continue;
    for (int d = 1; d < kBins; ++d)
      if (i - d >= 0 && all[size_t(i - d)] > 0) {
        filled[size_t(i)] = o[size_t(i - d)];
        break;
      } else if (i + d < kBins && all[size_t(i + d)] > 0) {
        filled[size_t(i)] = o[size_t(i + d)];
        break;
      }
  }
  for (size_t i = 0; i < size_t(kBins); ++i) t[i] = float(filled[i] / top);
  return t;
}

Model build_model(const std::vector<Quantity>& quantities, const std::vector<ClassStats>& classes,
                  const HierarchyParams& p) {
  std::vector<size_t> order(classes.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return classes[a].pixels > classes[b].pixels; });
  uint64_t total = 0;
  std::vector<std::array<uint64_t, kBins>> all(quantities.size(), std::array<uint64_t, kBins>{});
  for (const ClassStats& c : classes) {
    total += c.pixels;
    for (size_t q = 0; q < quantities.size(); ++q)
      for (size_t i = 0; i < size_t(kBins); ++i) all[q][i] += c.hist[q][i];
  }

  Model m;
  m.quantities = quantities;
  const ClassStats& widest = classes[order.front()];
  Layer root;
  root.name = "root";
  root.class_id = widest.id;
  root.colour = mean_colour(widest);
  root.constraints.resize(quantities.size());
  m.layers.push_back(root);
  for (const size_t i : order) {
    const ClassStats& c = classes[i];
    Layer l;
    l.name = "class" + std::to_string(c.id);
    l.parent = 0;
    l.class_id = c.id;
    l.colour = mean_colour(c);
    l.noise_scale = float(p.noise_scale);
    l.noise = p.noise;
    l.noise.seed = p.seed * 1000 + uint64_t(c.id);
    for (size_t q = 0; q < quantities.size(); ++q)
      l.constraints.push_back(p.odds ? odds_function(c.hist[q], all[q])
                                     : constraint_function(c.hist[q]));
    const int self = int(m.layers.size());
    m.layers.push_back(l);
    if (double(c.pixels) < p.large_fraction * double(total)) continue;
    for (int k = 0; k < p.children; ++k) {
      Layer child;
      child.name = l.name + "." + std::to_string(k);
      child.parent = self;
      child.bias = float(p.child_bias);
      child.noise_scale = float(p.child_noise_scale);
      child.noise = p.noise;
      child.noise.seed = l.noise.seed * 100 + uint64_t(k) + 1;
      child.noise.wavelength_m =
          p.noise.wavelength_m * (1 + 0.25 * jitter(p.seed, uint64_t(c.id), uint64_t(k), 3));
      for (size_t ch = 0; ch < 3; ++ch) {
        const double mean = c.sum[ch] / double(c.pixels);
        const double sd = std::sqrt(std::max(0.0, c.sum_sq[ch] / double(c.pixels) - mean * mean));
        child.colour[ch] = float(std::clamp(
            mean + p.colour_spread * sd * jitter(p.seed, uint64_t(c.id), uint64_t(k), ch), 0.0,
            255.0));
      }
      child.constraints.resize(quantities.size());
      m.layers.push_back(child);
    }
  }
  return m;
}

}  // namespace maquette::texture
