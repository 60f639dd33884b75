#include "assess_metrics.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "nearest_patches.h"

namespace maquette::synthesis {
namespace {

constexpr int kPatchFloats = kCoherenceSide * kCoherenceSide * 3;

// The 5 x 5 RGB patch centred on (x, y) of a width-wide image, appended to `out`; false (and
// nothing appended) when it leaves the image or has an unknown colour.
bool append_patch(const std::vector<float>& rgb, int width, int height, int x, int y,
                  std::vector<float>& out) {
  if (x < kCoherenceRadius || y < kCoherenceRadius || x + kCoherenceRadius >= width ||
      y + kCoherenceRadius >= height)
    return false;
  const size_t start = out.size();
  for (int dy = -kCoherenceRadius; dy <= kCoherenceRadius; ++dy)
    for (int dx = -kCoherenceRadius; dx <= kCoherenceRadius; ++dx)
      for (int k = 0; k < 3; ++k) {
        const float v = rgb[(size_t(y + dy) * size_t(width) + size_t(x + dx)) * 3 + size_t(k)];
        if (std::isnan(v)) {
          out.resize(start);
          return false;
        }
        out.push_back(v);
      }
  return true;
}

double ssd(const std::vector<float>& points, int32_t a, int32_t b) {
  double d = 0;
  for (int i = 0; i < kPatchFloats; ++i) {
    const double x = double(points[size_t(a) * kPatchFloats + size_t(i)]) -
                     double(points[size_t(b) * kPatchFloats + size_t(i)]);
    d += x * x;
  }
  return d;
}

// The points turned onto the principal axes of the first `n` (the exemplar's patches), largest
// variance first: a rotation keeps every distance, and the k-d tree then splits along the few
// axes that matter instead of 75 near-equal raw ones (many times fewer patches visited).
std::vector<float> principal_axes(const std::vector<float>& points, size_t n) {
  using Matrix = Eigen::Matrix<double, kPatchFloats, kPatchFloats>;
  using Vector = Eigen::Matrix<double, kPatchFloats, 1>;
  Vector mean = Vector::Zero();
  for (size_t i = 0; i < n; ++i)
    mean += Eigen::Map<const Eigen::Matrix<float, kPatchFloats, 1>>(&points[i * kPatchFloats])
                .cast<double>();
  mean /= double(n);
  Matrix scatter = Matrix::Zero();
  for (size_t i = 0; i < n; ++i) {
    const Vector v =
        Eigen::Map<const Eigen::Matrix<float, kPatchFloats, 1>>(&points[i * kPatchFloats])
            .cast<double>() -
        mean;
    scatter.selfadjointView<Eigen::Lower>().rankUpdate(v);
  }
  const Matrix covariance = scatter.selfadjointView<Eigen::Lower>();
  const Eigen::SelfAdjointEigenSolver<Matrix> solver(covariance);
  // Eigenvalues ascending: reversed, the largest first.
  const Eigen::Matrix<float, kPatchFloats, kPatchFloats> axes =
      solver.eigenvectors().rowwise().reverse().transpose().cast<float>();
  std::vector<float> out(points.size());
  using Patch = Eigen::Matrix<float, kPatchFloats, 1>;
  for (size_t i = 0; i < points.size() / kPatchFloats; ++i) {
    Eigen::Map<Patch> turned(&out[i * kPatchFloats]);
    turned = axes * Eigen::Map<const Patch>(&points[i * kPatchFloats]);
  }
  return out;
}

// Sum and count of the nearest exemplar patch's SSD over the counted pixels on the step grid.
void tally_coherence(const Exemplar& e, const AssessedImage& image, const PixelRect& counted,
                     int step, Tally& t) {
  std::vector<float> points;
  std::vector<int32_t> candidates, queries;
  for (int y = 0; y < e.height; ++y)
    for (int x = 0; x < e.width; ++x)
      if (!e.excluded[size_t(y) * size_t(e.width) + size_t(x)] &&
          append_patch(e.rgb, e.width, e.height, x, y, points))
        candidates.push_back(int32_t(candidates.size()));
  const auto w = int(image.rect.width), h = int(image.rect.height);
  for (int64_t row = counted.row0; row < counted.row0 + counted.height; ++row)
    for (int64_t col = counted.col0; col < counted.col0 + counted.width; ++col)
      if (col % step == 0 && row % step == 0 &&
          append_patch(image.rgb, w, h, int(col - image.rect.col0), int(row - image.rect.row0),
                       points))
        queries.push_back(int32_t(candidates.size() + queries.size()));
  if (candidates.empty() || queries.empty()) return;
  // The exact nearest (eps 0): the measure, not a synthesis's candidates.
  const std::vector<int32_t> nearest =
      nearest_patches(principal_axes(points, candidates.size()), kPatchFloats, candidates, queries,
                      1, 0.0f, [](int32_t, int32_t) { return true; });
  // The SSD itself from the colours (the rotation's float rounding left out).
  for (size_t q = 0; q < queries.size(); ++q)
    t.coherence_sum += ssd(points, queries[q], nearest[q]);
  t.coherence_patches += queries.size();
}

}  // namespace

Exemplar copied_exemplar(const ExemplarLevel& finest) {
  Exemplar e{finest.width,    finest.height,   finest.rgb,      finest.labels,
             finest.altitude, finest.excluded, finest.distance, finest.light};
  for (float& v : e.rgb) v = std::round(v * 255.0f);
  return e;
}

int histogram_bin(float r, float g, float b) {
  const auto level = [](float v) { return std::clamp(int(std::lround(v)), 0, 255) / 32; };
  return (level(r) * 8 + level(g)) * 8 + level(b);
}

void Tally::merge(const Tally& o) {
  pixels += o.pixels;
  labelled += o.labelled;
  label_matches += o.label_matches;
  for (const auto& [label, n] : o.labelled_by) labelled_by[label] += n;
  excluded += o.excluded;
  coherence_sum += o.coherence_sum;
  coherence_patches += o.coherence_patches;
  altitude_sum += o.altitude_sum;
  altitude_pixels += o.altitude_pixels;
  for (const auto& [pixel, n] : o.uses) uses[pixel] += n;
  for (const auto& [label, counts] : o.histograms) {
    auto& mine = histograms[label];
    mine.resize(kHistogramBins, 0);
    for (int i = 0; i < kHistogramBins; ++i) mine[size_t(i)] += counts[size_t(i)];
  }
}

Tally tally(const Exemplar& e, const AssessedImage& image, const PixelRect& counted,
            int coherence_step) {
  Tally t;
  const auto w = size_t(image.rect.width);
  for (int64_t row = counted.row0; row < counted.row0 + counted.height; ++row)
    for (int64_t col = counted.col0; col < counted.col0 + counted.width; ++col) {
      const size_t i = size_t(row - image.rect.row0) * w + size_t(col - image.rect.col0);
      const int32_t s = image.source[i];
      const uint8_t label = image.labels[i];
      const float* c = &image.rgb[3 * i];
      if (label != kUnknownLabel && !std::isnan(c[0] + c[1] + c[2])) {
        auto& h = t.histograms[label];
        h.resize(kHistogramBins, 0);
        ++h[size_t(histogram_bin(c[0], c[1], c[2]))];
      }
      if (s < 0) continue;
      ++t.pixels;
      ++t.uses[s];
      t.excluded += e.excluded[size_t(s)] != 0;
      if (label != kUnknownLabel) {
        ++t.labelled;
        ++t.labelled_by[label];
        t.label_matches += e.labels[size_t(s)] == label;
      }
      if (!image.altitude.empty() && !e.altitude.empty() && !std::isnan(image.altitude[i])) {
        t.altitude_sum += std::abs(double(image.altitude[i]) - double(e.altitude[size_t(s)]));
        ++t.altitude_pixels;
      }
    }
  tally_coherence(e, image, counted, coherence_step, t);
  return t;
}

std::vector<uint64_t> exemplar_histogram(const Exemplar& e, uint8_t label) {
  std::vector<uint64_t> h(kHistogramBins, 0);
  for (size_t i = 0; i < e.labels.size(); ++i)
    if (e.labels[i] == label && !e.excluded[i])
      ++h[size_t(histogram_bin(e.rgb[3 * i], e.rgb[3 * i + 1], e.rgb[3 * i + 2]))];
  return h;
}

uint64_t label_keeping_sources(const Exemplar& e, const std::map<uint8_t, uint64_t>& labelled,
                               uint64_t unlabelled) {
  std::map<uint8_t, uint64_t> allowed_by;
  for (size_t i = 0; i < e.labels.size(); ++i)
    if (!e.excluded[i]) ++allowed_by[e.labels[i]];
  uint64_t allowed = 0, drawn = 0;
  for (const auto& [label, n] : allowed_by) allowed += n;
  for (const auto& [label, n] : labelled) drawn += std::min(n, allowed_by[label]);
  return drawn + std::min(unlabelled, allowed - drawn);
}

Metrics metrics(const Exemplar& e, const Tally& t) {
  Metrics m;
  m.pixels = t.pixels;
  m.label_consistency = t.labelled ? double(t.label_matches) / double(t.labelled) : 1.0;
  m.excluded_pixels = t.excluded;
  m.allowed_pixels = uint64_t(std::count(e.excluded.begin(), e.excluded.end(), uint8_t(0)));
  m.coherence = t.coherence_patches ? t.coherence_sum / double(t.coherence_patches) : 0.0;
  uint64_t most = 0;
  for (const auto& [pixel, n] : t.uses) most = std::max(most, n);
  if (t.pixels) {
    m.distinct_source_fraction = double(t.uses.size()) / double(t.pixels);
    m.max_source_share = double(most) / double(t.pixels);
    m.distinct_source_bound = std::min(1.0, double(m.allowed_pixels) / double(t.pixels));
    m.distinct_source_label_bound =
        double(label_keeping_sources(e, t.labelled_by, t.pixels - t.labelled)) / double(t.pixels);
  }
  for (const auto& [label, counts] : t.histograms) {
    const double d = total_variation(counts, exemplar_histogram(e, label));
    m.histogram_distance[label] = d;
    m.worst_histogram_distance = std::max(m.worst_histogram_distance, d);
  }
  m.altitude_mismatch = t.altitude_pixels ? t.altitude_sum / double(t.altitude_pixels) : 0.0;
  return m;
}

}  // namespace maquette::synthesis
