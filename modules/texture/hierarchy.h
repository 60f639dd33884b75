// The layer hierarchy of a fitted model (paper 5.2.2 and 5.2.3): a root with the colour of the
// most widespread class, one level-1 layer per class with its mean colour and one constraint
// function per quantity (the class's histogram scaled to mean 0.5, clamped to [0, 1], or the
// class's odds per bin), and diversified children for the large classes.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "model.h"

namespace maquette::texture {

struct ClassStats {
  int id = 0;
  uint64_t pixels = 0;
  std::array<double, 3> sum{}, sum_sq{};          // RGB
  std::vector<std::array<uint64_t, kBins>> hist;  // per quantity
};

struct HierarchyParams {
  double noise_scale = 0.1;      // level-1 layers
  NoiseParams noise;             // level-1 layers (seed varied per layer)
  double large_fraction = 0.25;  // classes with at least this share of pixels get children
  int children = 2;
  double child_bias = 0.5, child_noise_scale = 0.6;  // children cover noise-shaped patches
  double colour_spread = 1;  // child colours: mean +- spread * standard deviation
  uint64_t seed = 1;
  bool odds = false;  // constraint functions: class odds per bin instead of scaled density
};

// Constraint function of a histogram: scaled so its mean is 0.5, clamped to [0, 1].
Table constraint_function(const std::array<uint64_t, kBins>& hist);

// Constraint function as the class's odds per bin, (n + 0.5) / (others + 0.5) clamped to
// [1/64, 64], divided by its largest value (0 where no class has pixels): prior-aware, and the
// product over quantities is proportional to the naive-Bayes odds of the class.
Table odds_function(const std::array<uint64_t, kBins>& hist,
                    const std::array<uint64_t, kBins>& all);

// `classes` in increasing id, each with pixels > 0. Level-1 layers in decreasing pixel count
// (ties: lower id first), so rarer types are evaluated later and overwrite where they fit.
Model build_model(const std::vector<Quantity>& quantities, const std::vector<ClassStats>& classes,
                  const HierarchyParams& p);

}  // namespace maquette::texture
