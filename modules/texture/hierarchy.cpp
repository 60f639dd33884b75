#include "hierarchy.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "noise.h"

namespace maquette::texture {
namespace {

std::array<float, 3> mean_colour(const ClassStats& c) {
  std::array<float, 3> m{};
  for (size_t k = 0; k < 3; ++k) m[k] = float(c.sum[k] / double(c.colour_pixels));
  return m;
}

}  // namespace

ColourSpread colour_spread(const ClassStats& c) {
  ColourSpread out;
  const double n = double(c.colour_pixels);
  for (size_t k = 0; k < 3; ++k) out.mean[k] = c.sum[k] / n;
  std::array<std::array<double, 3>, 3> cov{};
  for (size_t k = 0; k < 3; ++k) cov[k][k] = c.sum_sq[k] / n - out.mean[k] * out.mean[k];
  for (size_t i = 0; i < 3; ++i) {
    const auto [a, b] = kCrossPairs[i];
    cov[a][b] = cov[b][a] = c.sum_cross[i] / n - out.mean[a] * out.mean[b];
  }
  // Power iteration from the grey axis (usually close: brightness varies most).
  std::array<double, 3> e = {1, 1, 1};
  double lambda = 0;
  for (int it = 0; it < 200; ++it) {
    std::array<double, 3> f{};
    for (size_t a = 0; a < 3; ++a)
      for (size_t b = 0; b < 3; ++b) f[a] += cov[a][b] * e[b];
    const double norm = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    if (!(norm > 0)) break;
    for (size_t a = 0; a < 3; ++a) e[a] = f[a] / norm;
    lambda = norm;
  }
  const double norm = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
  const double sign = e[0] + e[1] + e[2] < 0 ? -1 : 1;  // + is lighter
  for (size_t a = 0; a < 3; ++a) out.axis[a] = sign * e[a] / norm;
  out.sd = std::sqrt(std::max(0.0, lambda));
  return out;
}

std::vector<double> noise_samples(const NoiseParams& noise, double pixel_m) {
  // 256 x 256 points 1/7.3 of a wavelength apart (off the lattice) on the plane tangent to the
  // globe at (0 N, 0 E): 35 wavelengths across, so that the tails of N (which a bias far from
  // 0.5 reads) are sampled too (with 64 x 64, Zion's darkest class came out CIEDE2000 7 lighter).
  const NoiseField field(noise);
  const double step = noise.wavelength_m / 7.3;
  constexpr int kSide = 256;
  std::vector<double> out;
  for (int i = 0; i < kSide; ++i)
    for (int j = 0; j < kSide; ++j) {
      const Vec3d x = {6371007.2, step * i, step * j};
      double n = 0;
      for (int o = 0; o < field.octaves(); ++o)
        if (field.wavelength_m(o) >= 2 * pixel_m) n += field.amplitude(o) * field.octave(o, x);
      out.push_back(std::clamp(n / field.norm(), -1.0, 1.0));
    }
  return out;
}

std::array<double, 2> coverage_moments(const std::vector<double>& noise, double bias,
                                       double scale) {
  double sum = 0, sum_sq = 0;
  for (const double n : noise) {
    const double c = std::clamp(bias + scale * n, 0.0, 1.0);
    sum += c, sum_sq += c * c;
  }
  const double k = double(noise.size()), mean = sum / k;
  return {mean, std::sqrt(std::max(0.0, sum_sq / k - mean * mean))};
}

Table constraint_function(const std::array<uint64_t, kBins>& hist) {
  const double total = double(std::accumulate(hist.begin(), hist.end(), uint64_t(0)));
  Table t{};
  if (total == 0) return t;
  const double k = 0.5 / (total / kBins);
  for (int i = 0; i < kBins; ++i) t[size_t(i)] = float(std::min(1.0, double(hist[size_t(i)]) * k));
  return t;
}

Table odds_function(const std::array<uint64_t, kBins>& hist, const std::array<uint64_t, kBins>& all,
                    bool categorical) {
  Table t{};
  double top = 0;
  std::array<double, kBins> o{};
  const auto odds = [](double n, double others) {
    return std::clamp((n + 0.5) / (others + 0.5), 1.0 / 64, 64.0);
  };
  double n = 0, others = 0;
  for (size_t i = 0; i < size_t(kBins); ++i)
    if (all[i] > 0) {
      o[i] = odds(double(hist[i]), double(all[i] - hist[i]));
      top = std::max(top, o[i]);
      n += double(hist[i]), others += double(all[i] - hist[i]);
    }
  if (top == 0) return t;
  if (categorical) {
    for (size_t i = 0; i < size_t(kBins); ++i)
      t[i] = float((all[i] > 0 ? o[i] : std::min(odds(n, others), top)) / top);
    return t;
  }
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
  std::vector<std::array<uint64_t, kBins>> all(quantities.size(), std::array<uint64_t, kBins>{});
  for (const ClassStats& c : classes)
    for (size_t q = 0; q < quantities.size(); ++q)
      for (size_t i = 0; i < size_t(kBins); ++i) all[q][i] += c.hist[q][i];

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
    if (i == order.front()) {
      // The most widespread type is the base material, like the root: it covers whatever the
      // later layers leave (it is the root's class there anyway), with its own colours and
      // variation instead of the root's flat colour where its constraints would be low.
      l.noise_scale = 0;
      l.constraints.resize(quantities.size());
    } else {
      for (size_t q = 0; q < quantities.size(); ++q)
        l.constraints.push_back(
            p.odds ? odds_function(c.hist[q], all[q], is_categorical(quantities[q].name))
                   : constraint_function(c.hist[q]));
    }
    const int self = int(m.layers.size());
    m.layers.push_back(l);
    if (!p.variation) continue;
    Layer v;
    v.name = l.name + ".variation";
    v.parent = self;
    v.noise_scale = float(p.variation_noise_scale);
    v.noise = p.noise;
    v.noise.seed = l.noise.seed * 100 + 1;
    v.constraints.resize(quantities.size());
    // The colour is L + D C along e, C the child's coverage of mean mu and deviation sigma: the
    // class's mean m and deviation sd along e when D = sd / sigma and L = m - D mu. The child's
    // bias sets mu: 0.5 where both ends are colours; a dark class (a bright tail) needs a lower
    // one, a light class a higher one, so the ends stay in 0..255 (a clamped end would move the
    // mean). Biases from 0.5 outwards; when none fits, 0.5 with D shrunk until the ends fit.
    const ColourSpread spread = colour_spread(c);
    const std::vector<double> noise = noise_samples(v.noise, p.pixel_m);
    const auto ends = [&](double bias, double shrink) {
      const auto [mu, sigma] = coverage_moments(noise, bias, p.variation_noise_scale);
      const double d = sigma > 0 ? shrink * spread.sd / sigma : 0;
      std::array<std::array<double, 3>, 2> e{};
      for (size_t k = 0; k < 3; ++k) {
        e[0][k] = spread.mean[k] - d * mu * spread.axis[k];
        e[1][k] = spread.mean[k] + d * (1 - mu) * spread.axis[k];
      }
      return e;
    };
    const auto fits = [](const std::array<std::array<double, 3>, 2>& e) {
      for (const auto& end : e)
        for (const double x : end)
          if (x < 0 || x > 255) return false;
      return true;
    };
    double bias = 0.5, shrink = 1;
    for (int step = 0; step <= 36; ++step) {  // 0.5, 0.475, 0.525, 0.45, ... 0.05, 0.95
      const double b = 0.5 + (step % 2 ? -1 : 1) * 0.025 * ((step + 1) / 2);
      if (fits(ends(b, 1))) {
        bias = b;
        break;
      }
      if (step == 36)
        while (shrink > 0 && !fits(ends(0.5, shrink))) shrink -= 0.01;
    }
    v.bias = float(bias);
    const auto e = ends(bias, std::max(shrink, 0.0));
    for (size_t k = 0; k < 3; ++k) {
      m.layers[size_t(self)].colour[k] = float(std::clamp(e[0][k], 0.0, 255.0));  // rounding
      v.colour[k] = float(std::clamp(e[1][k], 0.0, 255.0));
    }
    m.layers.push_back(v);
  }
  return m;
}

}  // namespace maquette::texture
