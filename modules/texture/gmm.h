// Gaussian mixture over the occupied bins of a colour histogram (colour-wheel coordinates
// (s cos h, s sin h[, v]), hs_histogram.h), fitted by EM for binned data: a bin's pixels lie
// anywhere in the bin (BinPoint::spread), so a component of covariance C gives a bin centre x
// the density N(x; mean, C + spread). This is the "extreme deconvolution" EM of Bovy, Hogg and
// Roweis (2011, Ann. Appl. Stat. 5:1657): the covariances are those of the colours, not of the
// bin centres, and extra components gain nothing from the binning itself (which keeps BIC
// meaningful). Deterministic: seeded from a k-means partition (weights = its pixel fractions,
// means = its centres, covariances = its within-cluster scatter), at most kGmmIterations EM
// steps, stopped when the log-likelihood gains less than kGmmTolerance of itself; every
// covariance gets kGmmRegularisation on its diagonal so it stays positive definite when a
// component holds a single bin.
//
// The log-likelihood reported (and used by BIC) is that of the bin counts: each component's
// densities at the bin centres (covariance + spread) times the bins' volumes, normalised over
// every bin of the histogram, so that a component narrower than a bin cannot claim more than
// the whole bin (the densities alone would reward components collapsing onto single bins).
#pragma once

#include <vector>

#include "kmeans.h"

namespace maquette::texture {

inline constexpr int kGmmIterations = 300;
inline constexpr double kGmmTolerance = 1e-7;
inline constexpr double kGmmRegularisation = 1e-6;

struct Gaussian {
  double weight = 0;
  Point mean{};
  Matrix covariance{};
};

struct Mixture {
  int dims = 2;
  std::vector<Gaussian> components;
  double log_likelihood = 0;  // sum over pixels of the log probability of their bin
  int iterations = 0;         // EM steps after the seed
};

Mixture fit_gmm(const std::vector<BinPoint>& bins, ColourSpace space, const Partition& seed);

// Bayesian information criterion -2 log L + p log n, p = k (dims + dims (dims + 1) / 2) + k - 1,
// n the number of pixels.
double bic(const Mixture& mixture, double pixels);

// Component of largest posterior probability for each bin (first of equals).
std::vector<size_t> most_likely_component(const std::vector<BinPoint>& bins,
                                          const Mixture& mixture);

}  // namespace maquette::texture
