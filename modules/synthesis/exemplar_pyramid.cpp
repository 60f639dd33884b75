#include "exemplar_pyramid.h"

#include <tbb/parallel_for.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cstdlib>

#include "class_edges.h"
#include "core/error.h"
#include "nearest_patches.h"
#include "spread_regions.h"

namespace maquette::synthesis {
namespace {

// The binomial filter along one axis with clamped borders, then every second sample kept.
std::vector<float> blur_decimate(const std::vector<float>& in, int w, int h, int channels, int& ow,
                                 int& oh) {
  static constexpr float kTaps[5] = {1 / 16.f, 4 / 16.f, 6 / 16.f, 4 / 16.f, 1 / 16.f};
  ow = (w + 1) / 2;
  oh = (h + 1) / 2;
  std::vector<float> rows(size_t(ow) * size_t(h) * size_t(channels), 0.0f);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < ow; ++x)
      for (int t = 0; t < 5; ++t) {
        const int sx = std::clamp(2 * x + t - 2, 0, w - 1);
        for (int c = 0; c < channels; ++c)
          rows[(size_t(y) * size_t(ow) + size_t(x)) * size_t(channels) + size_t(c)] +=
              kTaps[t] * in[(size_t(y) * size_t(w) + size_t(sx)) * size_t(channels) + size_t(c)];
      }
  std::vector<float> out(size_t(ow) * size_t(oh) * size_t(channels), 0.0f);
  for (int y = 0; y < oh; ++y)
    for (int t = 0; t < 5; ++t) {
      const int sy = std::clamp(2 * y + t - 2, 0, h - 1);
      for (int x = 0; x < ow; ++x)
        for (int c = 0; c < channels; ++c)
          out[(size_t(y) * size_t(ow) + size_t(x)) * size_t(channels) + size_t(c)] +=
              kTaps[t] * rows[(size_t(sy) * size_t(ow) + size_t(x)) * size_t(channels) + size_t(c)];
    }
  return out;
}

ExemplarLevel coarser(const ExemplarLevel& f) {
  ExemplarLevel c;
  c.rgb = blur_decimate(f.rgb, f.width, f.height, 3, c.width, c.height);
  if (!f.altitude.empty())
    c.altitude = blur_decimate(f.altitude, f.width, f.height, 1, c.width, c.height);
  if (!f.distance.empty())
    c.distance = blur_decimate(f.distance, f.width, f.height, 1, c.width, c.height);
  if (!f.light.empty()) c.light = blur_decimate(f.light, f.width, f.height, 1, c.width, c.height);
  c.labels.resize(size_t(c.width) * size_t(c.height));
  c.excluded.resize(c.labels.size());
  for (int y = 0; y < c.height; ++y)
    for (int x = 0; x < c.width; ++x) {
      const size_t i = size_t(c.index(x, y));
      c.labels[i] = f.labels[size_t(f.index(2 * x, 2 * y))];
      uint8_t any = 0;
      for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx)
          any |= f.excluded[size_t(
              f.index(std::min(2 * x + dx, f.width - 1), std::min(2 * y + dy, f.height - 1)))];
      c.excluded[i] = any;
    }
  return c;
}

// The PCA basis of the neighbourhoods of the paintings' pixels at level `l` (painting by
// painting, row by row).
PatchBasis fit_basis(const ExemplarLevel& level, int l, const std::vector<Placement>& paintings) {
  // Fixed sizes: no allocation per pixel.
  using Vector = Eigen::Matrix<double, kPatchValues, 1>;
  Vector mean = Vector::Zero();
  Eigen::Matrix<double, kPatchValues, kPatchValues> scatter =
      Eigen::Matrix<double, kPatchValues, kPatchValues>::Zero();
  double n = 0;
  for (const Placement& at : paintings) {
    const int x0 = at.x0 >> l, width = (at.width + (1 << l) - 1) >> l;
    const int height = (at.height + (1 << l) - 1) >> l;
    for (int y = 0; y < height; ++y)
      for (int x = x0; x < x0 + width; ++x) {
        const auto p = level.patch(x, y);
        const Vector v =
            Eigen::Map<const Eigen::Matrix<float, kPatchValues, 1>>(p.data()).cast<double>();
        mean += v;
        scatter.selfadjointView<Eigen::Lower>().rankUpdate(v);
      }
    n += double(width) * double(height);
  }
  mean /= n;
  Eigen::MatrixXd covariance = scatter.selfadjointView<Eigen::Lower>();
  covariance = covariance / n - mean * mean.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(covariance);
  PatchBasis basis;
  for (int i = 0; i < kPatchValues; ++i) basis.mean[size_t(i)] = float(mean[i]);
  // Eigenvalues ascending: the last columns are the principal axes. Each axis' sign is fixed
  // (largest component positive) so that the features do not depend on the solver's choice.
  for (int a = 0; a < kFeatureDims; ++a) {
    Eigen::VectorXd axis = solver.eigenvectors().col(kPatchValues - 1 - a);
    Eigen::Index largest = 0;
    axis.cwiseAbs().maxCoeff(&largest);
    if (axis[largest] < 0) axis = -axis;
    for (int i = 0; i < kPatchValues; ++i) basis.axes[size_t(a)][size_t(i)] = float(axis[i]);
  }
  return basis;
}

// The k similar patches are searched approximately (Arya, Mount, Netanyahu, Silverman & Wu 1998,
// "An optimal algorithm for approximate nearest neighbor searching in fixed dimensions"): each
// j-th within 1.25 times the true j-th's distance. Measured in session 26 (benchmarks/README.md):
// the analysis's CPU -34 %, every gate of the 5-seed driver still met; eps 0.5 lost two of them.
constexpr float kSimilarEps = 0.25f;

void analyse_level(ExemplarLevel& level, int l, int k, const std::vector<Placement>& paintings) {
  const int n = level.width * level.height;
  for (int32_t i = 0; i < n; ++i)
    if (!level.excluded[size_t(i)]) {
      level.allowed.push_back(i);
      level.by_label[level.labels[size_t(i)]].push_back(i);
    }
  if (level.allowed.empty())
    throw Error("synthesis: the exemplar has no pixel left to copy at level " + std::to_string(l) +
                ", " + std::to_string(level.width) + " x " + std::to_string(level.height) +
                " (a pixel there is excluded when any of the 2 x 2 below it is: the exclusions "
                "cover every block; exclude less, or lower exemplar_scale)");
  level.basis = fit_basis(level, l, paintings);
  level.features.resize(size_t(n) * kFeatureDims);
  // Each row's features on their own (in parallel).
  tbb::parallel_for(0, level.height, [&level](int y) {
    for (int x = 0; x < level.width; ++x) {
      const auto f = level.basis.project(level.patch(x, y));
      std::copy(f.begin(), f.end(),
                level.features.begin() + ptrdiff_t(level.index(x, y)) * kFeatureDims);
    }
  });
  // Candidates farther than a patch from the query: a neighbourhood overlapping the query's is
  // similar by construction and would only offer coherence the candidates already have.
  const int w = level.width;
  level.similar = nearest_patches(level.features, kFeatureDims, level.allowed, level.allowed, k,
                                  kSimilarEps, [w](int32_t q, int32_t c) {
                                    return std::abs(q % w - c % w) > kPatchSide - 1 ||
                                           std::abs(q / w - c / w) > kPatchSide - 1;
                                  });
  // Indexed by pixel: excluded pixels get none.
  std::vector<int32_t> by_pixel(size_t(n) * size_t(k), -1);
  for (size_t a = 0; a < level.allowed.size(); ++a)
    std::copy_n(level.similar.begin() + ptrdiff_t(a) * k, k,
                by_pixel.begin() + ptrdiff_t(level.allowed[a]) * k);
  level.similar = std::move(by_pixel);
}

}  // namespace

std::array<float, kFeatureDims> PatchBasis::project(
    const std::array<float, kPatchValues>& patch) const {
  std::array<float, kFeatureDims> f{};
  for (int a = 0; a < kFeatureDims; ++a) {
    float s = 0;
    for (int i = 0; i < kPatchValues; ++i)
      s += axes[size_t(a)][size_t(i)] * (patch[size_t(i)] - mean[size_t(i)]);
    f[size_t(a)] = s;
  }
  return f;
}

std::array<float, kPatchValues> ExemplarLevel::patch(int x, int y) const {
  std::array<float, kPatchValues> p{};
  size_t o = 0;
  for (int dy = -kPatchRadius; dy <= kPatchRadius; ++dy)
    for (int dx = -kPatchRadius; dx <= kPatchRadius; ++dx) {
      const size_t i =
          size_t(index(std::clamp(x + dx, 0, width - 1), std::clamp(y + dy, 0, height - 1)));
      for (int c = 0; c < 3; ++c) p[o++] = rgb[3 * i + size_t(c)];
    }
  return p;
}

ExemplarPyramid analyse_exemplar(const Exemplar& exemplar, int levels, int k,
                                 const std::vector<Placement>& paintings) {
  ExemplarPyramid pyramid;
  pyramid.k = k;
  ExemplarLevel finest;
  finest.width = exemplar.width;
  finest.height = exemplar.height;
  finest.rgb.resize(exemplar.rgb.size());
  for (size_t i = 0; i < exemplar.rgb.size(); ++i) finest.rgb[i] = exemplar.rgb[i] / 255.0f;
  finest.labels = exemplar.labels;
  finest.altitude = exemplar.altitude;
  finest.distance = exemplar.distance;
  finest.light = exemplar.light;
  finest.excluded = exemplar.excluded;
  pyramid.levels.push_back(std::move(finest));
  for (int l = 1; l < levels; ++l) pyramid.levels.push_back(coarser(pyramid.levels.back()));
  const std::vector<Placement> whole{{0, exemplar.width, exemplar.height}};
  for (int l = 0; l < levels; ++l) {
    ExemplarLevel& level = pyramid.levels[size_t(l)];
    analyse_level(level, l, k, paintings.empty() ? whole : paintings);
    level.region_quantile = region_quantiles(level);
  }
  pyramid.levels[0].class_edges = class_edge_places(pyramid.levels[0]);
  return pyramid;
}

}  // namespace maquette::synthesis
