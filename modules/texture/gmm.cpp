#include "gmm.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace maquette::texture {
namespace {

constexpr double kNegligible = 1e-12;

// Cholesky factor L (L L^T = A) of a symmetric positive-definite dims x dims matrix.
class Cholesky {
 public:
  Cholesky(const Matrix& a, int dims) : dims_(dims) {
    double det = 1;
    for (size_t i = 0; i < size_t(dims); ++i)
      for (size_t j = 0; j <= i; ++j) {
        double s = a[i][j];
        for (size_t q = 0; q < j; ++q) s -= l_[i][q] * l_[j][q];
        if (i == j) {
          l_[i][i] = std::sqrt(s);
          det *= s;
        } else {
          l_[i][j] = s / l_[j][j];
        }
      }
    log_det_ = std::log(det);
  }

  double log_det() const { return log_det_; }

  // z with L z = b: |z|^2 = b^T A^-1 b.
  Point whiten(const Point& b) const {
    Point z{};
    for (size_t i = 0; i < size_t(dims_); ++i) {
      double s = b[i];
      for (size_t j = 0; j < i; ++j) s -= l_[i][j] * z[j];
      z[i] = s / l_[i][i];
    }
    return z;
  }

  Point solve(const Point& b) const {  // A^-1 b
    Point x = whiten(b);
    for (size_t i = size_t(dims_); i-- > 0;) {
      for (size_t j = i + 1; j < size_t(dims_); ++j) x[i] -= l_[j][i] * x[j];
      x[i] /= l_[i][i];
    }
    return x;
  }

 private:
  int dims_;
  Matrix l_{};
  double log_det_ = 0;
};

Matrix sum(const Matrix& a, const Matrix& b) {
  Matrix out{};
  for (size_t i = 0; i < 3; ++i)
    for (size_t j = 0; j < 3; ++j) out[i][j] = a[i][j] + b[i][j];
  return out;
}

Point difference(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

// log(weight) + log N(bin centre; mean, covariance + spread).
double log_density(const Gaussian& g, const BinPoint& bin, int dims) {
  const Cholesky t(sum(g.covariance, bin.spread), dims);
  const Point z = t.whiten(difference(bin.x, g.mean));
  double q = 0;
  for (size_t d = 0; d < size_t(dims); ++d) q += z[d] * z[d];
  return std::log(g.weight) - 0.5 * (t.log_det() + dims * std::log(2 * M_PI) + q);
}

// log(sum(exp(terms))), at least one term finite.
double log_sum_exp(const std::vector<double>& terms) {
  const double top = *std::max_element(terms.begin(), terms.end());
  double total = 0;
  for (const double t : terms) total += std::exp(t - top);
  return top + std::log(total);
}

// Posterior probabilities of the components for one bin into `post`; returns log p(bin).
double posterior(const Mixture& m, const BinPoint& bin, std::vector<double>& post) {
  for (size_t c = 0; c < m.components.size(); ++c)
    post[c] = log_density(m.components[c], bin, m.dims);
  const double log_p = log_sum_exp(post);
  for (double& p : post) p = std::exp(p - log_p);
  return log_p;
}

void regularise(Matrix& c, int dims) {
  for (size_t d = 0; d < size_t(dims); ++d) c[d][d] += kGmmRegularisation;
}

// The M step of extreme deconvolution: the pixels of bin i under component c are expected at
// b = mean + C T^-1 (x - mean) with covariance C - C T^-1 C, T = C + spread; weights, means and
// covariances are their responsibility-weighted moments. resp[i * k + c]; a component without
// any responsibility keeps its parameters. Responsibilities below kNegligible are skipped (most
// bins are far from most components).
void maximise(const std::vector<BinPoint>& bins, const std::vector<double>& resp, Mixture& m) {
  const size_t k = m.components.size(), dims = size_t(m.dims);
  double total = 0;
  for (const BinPoint& b : bins) total += b.w;
  for (size_t c = 0; c < k; ++c) {
    Gaussian& g = m.components[c];
    double n = 0;
    Point first{};
    Matrix second{};
    for (size_t i = 0; i < bins.size(); ++i) {
      if (resp[i * k + c] < kNegligible) continue;
      const double r = bins[i].w * resp[i * k + c];
      const Cholesky t(sum(g.covariance, bins[i].spread), m.dims);
      const Point shift = t.solve(difference(bins[i].x, g.mean));
      std::array<Point, 3> c_inv_t{};  // columns T^-1 C
      for (size_t col = 0; col < dims; ++col)
        c_inv_t[col] = t.solve({g.covariance[0][col], g.covariance[1][col], g.covariance[2][col]});
      Point b = g.mean;
      for (size_t a = 0; a < dims; ++a)
        for (size_t q = 0; q < dims; ++q) b[a] += g.covariance[a][q] * shift[q];
      n += r;
      for (size_t a = 0; a < dims; ++a) {
        first[a] += r * b[a];
        for (size_t e = 0; e <= a; ++e) {
          double spread = g.covariance[a][e];
          for (size_t q = 0; q < dims; ++q) spread -= g.covariance[a][q] * c_inv_t[e][q];
          second[a][e] += r * (b[a] * b[e] + spread);
        }
      }
    }
    if (!(n > 0)) continue;
    g.weight = n / total;
    for (size_t a = 0; a < dims; ++a) g.mean[a] = first[a] / n;
    for (size_t a = 0; a < dims; ++a)
      for (size_t e = 0; e <= a; ++e)
        g.covariance[a][e] = g.covariance[e][a] = second[a][e] / n - g.mean[a] * g.mean[e];
    regularise(g.covariance, m.dims);
  }
}

// The seed: each k-means cluster's pixel fraction, mean and scatter of its bin centres.
Mixture seed_mixture(const std::vector<BinPoint>& bins, int dims, const Partition& p) {
  Mixture m;
  m.dims = dims;
  m.components.resize(p.centres.size());
  double total = 0;
  for (const BinPoint& b : bins) total += b.w;
  for (size_t i = 0; i < bins.size(); ++i) {
    Gaussian& g = m.components[p.assign[i]];
    g.weight += bins[i].w / total;
    const Point d = difference(bins[i].x, p.centres[p.assign[i]]);
    for (size_t a = 0; a < 3; ++a)
      for (size_t e = 0; e < 3; ++e) g.covariance[a][e] += bins[i].w * d[a] * d[e];
  }
  for (size_t c = 0; c < p.centres.size(); ++c) {
    Gaussian& g = m.components[c];
    g.mean = p.centres[c];
    for (auto& row : g.covariance)
      for (double& v : row) v = g.weight > 0 ? v / (g.weight * total) : 0;
    regularise(g.covariance, dims);
  }
  return m;
}

// Sum over the pixels of the log probability of their bin: each component's densities at the
// bin centres times the bins' volumes, normalised over every bin of the histogram.
double binned_log_likelihood(const std::vector<BinPoint>& bins, ColourSpace space,
                             const Mixture& m) {
  const std::vector<BinPoint> every_bin = all_bins(space);
  std::vector<double> log_norm;  // log(sum of density x volume over all bins / weight)
  for (const Gaussian& g : m.components) {
    double z = 0;
    for (const BinPoint& b : every_bin) z += std::exp(log_density(g, b, m.dims)) * b.volume;
    log_norm.push_back(g.weight > 0 ? std::log(z / g.weight) : 0);
  }
  double sum = 0;
  std::vector<double> terms(m.components.size());
  for (const BinPoint& b : bins) {
    for (size_t c = 0; c < terms.size(); ++c)
      terms[c] = log_density(m.components[c], b, m.dims) - log_norm[c];  // -inf if weight 0
    sum += b.w * (log_sum_exp(terms) + std::log(b.volume));
  }
  return sum;
}

}  // namespace

Mixture fit_gmm(const std::vector<BinPoint>& bins, ColourSpace space, const Partition& seed) {
  Mixture m = seed_mixture(bins, histogram_dims(space), seed);
  const size_t k = m.components.size();
  std::vector<double> resp(bins.size() * k), post(k);
  double previous = -std::numeric_limits<double>::infinity();
  for (m.iterations = 0;; ++m.iterations) {
    double log_likelihood = 0;  // of the bin centres under extreme deconvolution
    for (size_t i = 0; i < bins.size(); ++i) {
      log_likelihood += bins[i].w * posterior(m, bins[i], post);
      std::copy(post.begin(), post.end(), resp.begin() + std::ptrdiff_t(i * k));
    }
    if (m.iterations == kGmmIterations ||
        log_likelihood - previous <= kGmmTolerance * std::abs(log_likelihood))
      break;
    previous = log_likelihood;
    maximise(bins, resp, m);
  }
  m.log_likelihood = binned_log_likelihood(bins, space, m);
  return m;
}

double bic(const Mixture& m, double pixels) {
  const double k = double(m.components.size()), d = m.dims;
  return -2 * m.log_likelihood + (k * (d + d * (d + 1) / 2) + k - 1) * std::log(pixels);
}

std::vector<size_t> most_likely_component(const std::vector<BinPoint>& bins, const Mixture& m) {
  std::vector<size_t> out(bins.size(), 0);
  std::vector<double> post(m.components.size());
  for (size_t i = 0; i < bins.size(); ++i) {
    posterior(m, bins[i], post);
    out[i] = size_t(std::max_element(post.begin(), post.end()) - post.begin());
  }
  return out;
}

}  // namespace maquette::texture
