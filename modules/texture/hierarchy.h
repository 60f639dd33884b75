// The layer hierarchy of a fitted model (paper 5.2.2 and 5.2.3): a root with the colour of the
// most widespread class, one level-1 layer per class with its mean colour and one constraint
// function per quantity (none for the most widespread class: the base material everywhere) (the
// class's histogram scaled to mean 0.5, clamped to [0, 1], or the class's odds per bin), and a
// variation child per class that gives it the colour spread of the imagery.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "model.h"

namespace maquette::texture {

inline constexpr std::array<std::array<size_t, 2>, 3> kCrossPairs = {{{0, 1}, {0, 2}, {1, 2}}};

struct ClassStats {
  int id = 0;
  uint64_t pixels = 0;
  // The colour sums are over colour_pixels of them (all, or those whose own colour class is
  // this class: texture.fit's inputs.colour_classes).
  uint64_t colour_pixels = 0;
  std::array<double, 3> sum{}, sum_sq{};          // RGB
  std::array<double, 3> sum_cross{};              // products of the kCrossPairs channels
  std::vector<std::array<uint64_t, kBins>> hist;  // per quantity
};

struct HierarchyParams {
  double noise_scale = 0.1;  // level-1 layers
  NoiseParams noise;         // level-1 layers (seed varied per layer)
  // Variation: each class is drawn between two colours on its principal colour axis (the
  // level-1 layer and its child), mixed by the child's coverage clamp(b + s N): the ends and b
  // are chosen so that the mean and the spread along the axis are the class's.
  bool variation = true;
  double variation_noise_scale = 1.5;  // s
  double pixel_m = 0;                  // of the fitted image: the resolution sd(C) is taken at
  uint64_t seed = 1;
  bool odds = false;  // constraint functions: class odds per bin instead of scaled density
};
// Constraint function of a histogram: scaled so its mean is 0.5, clamped to [0, 1].
Table constraint_function(const std::array<uint64_t, kBins>& hist);

// Constraint function as the class's odds per bin, (n + 0.5) / (others + 0.5) clamped to
// [1/64, 64], divided by its largest value: prior-aware, and the product over quantities is
// proportional to the naive-Bayes odds of the class. A bin where no class has pixels takes the
// odds of the nearest bin with pixels, or for a categorical quantity (an unseen code says
// nothing) the class's odds over all bins.
Table odds_function(const std::array<uint64_t, kBins>& hist, const std::array<uint64_t, kBins>& all,
                    bool categorical = false);

// `classes` in increasing id, each with pixels > 0. Level-1 layers in decreasing pixel count
// (ties: lower id first), so rarer types are evaluated later and overwrite where they fit.
// The mean colour and the principal axis of the class's colours: unit vector e and standard
// deviation along it (sqrt of the covariance's largest eigenvalue).
struct ColourSpread {
  std::array<double, 3> mean{}, axis{};
  double sd = 0;
};
ColourSpread colour_spread(const ClassStats& c);

// N(x) at 256 x 256 positions x, N the noise of `noise` as texture.procedural evaluates it on
// pixels of `pixel_m` (octaves shorter than 2 pixels left out, their mean 0; pixel_m 0: every
// octave).
std::vector<double> noise_samples(const NoiseParams& noise, double pixel_m);

// Mean and standard deviation of the coverage clamp(bias + scale N) over `noise` samples: how
// much of a colour difference a variation child with this noise passes on, and how.
std::array<double, 2> coverage_moments(const std::vector<double>& noise, double bias, double scale);

Model build_model(const std::vector<Quantity>& quantities, const std::vector<ClassStats>& classes,
                  const HierarchyParams& p);

}  // namespace maquette::texture
