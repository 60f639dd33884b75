// The transfer's measures (assess_metrics.h) on analytic cases: an exact copy of part of the
// exemplar, one source pixel repeated, constant colours a known distance apart, histograms of
// images of known colours, a known altitude ramp; the k-d tree's coherence against a brute-force
// scan; a tally split into windows and merged equals the whole one.
#include "../assess_metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>

#include "../pixel_hash.h"
#include "painted_exemplar.h"

namespace maquette::synthesis {
namespace {

// width x height pixels of hashed colours (0..255 integers, so no two 5 x 5 patches are
// equal), label 0 on the left half and 1 on the right, altitude x / (width - 1), none excluded.
Exemplar noise_exemplar(int width, int height, uint64_t seed) {
  return test::painted_exemplar(width, height, true, [seed](Exemplar& e, int x, int, size_t i) {
    for (size_t k = 0; k < 3; ++k) e.rgb[3 * i + k] = float(splitmix64_mix(seed + 3 * i + k) % 256);
    e.labels[i] = x >= e.width / 2 ? 1 : 0;
    e.altitude[i] = float(x) / float(e.width - 1);
  });
}

Exemplar constant_exemplar(int width, int height, float grey) {
  Exemplar e = noise_exemplar(width, height, 0);
  std::fill(e.rgb.begin(), e.rgb.end(), grey);
  return e;
}

// The exemplar's window (x0, y0, w, h) copied exactly, at global pixel (col0, row0), with the
// exemplar's labels as target labels and its altitude as target altitude.
AssessedImage copy_of(const Exemplar& e, int x0, int y0, int w, int h, int64_t col0, int64_t row0) {
  AssessedImage a;
  a.rect = {col0, row0, w, h};
  for (int y = y0; y < y0 + h; ++y)
    for (int x = x0; x < x0 + w; ++x) {
      const int32_t s = y * e.width + x;
      for (size_t k = 0; k < 3; ++k) a.rgb.push_back(e.rgb[3 * size_t(s) + k]);
      a.source.push_back(s);
      a.labels.push_back(e.labels[size_t(s)]);
      a.altitude.push_back(e.altitude[size_t(s)]);
    }
  return a;
}

TEST(AssessMetrics, AnExactCopyIsCoherentDistinctAndConsistent) {
  const Exemplar e = noise_exemplar(40, 30, 1);
  const AssessedImage a = copy_of(e, 5, 4, 30, 20, 1000, -7);
  const Metrics m = metrics(e, tally(e, a, a.rect, 1));
  EXPECT_EQ(m.pixels, 600u);
  EXPECT_EQ(m.label_consistency, 1.0);
  EXPECT_EQ(m.excluded_pixels, 0u);
  EXPECT_EQ(m.coherence, 0.0);  // every inner patch is the exemplar's own
  EXPECT_DOUBLE_EQ(m.distinct_source_fraction, 1.0);
  EXPECT_DOUBLE_EQ(m.max_source_share, 1.0 / 600);
  EXPECT_EQ(m.altitude_mismatch, 0.0);
}

TEST(AssessMetrics, CountsWrongLabelsAndAltitude) {
  const Exemplar e = noise_exemplar(40, 30, 2);
  AssessedImage a = copy_of(e, 0, 0, 40, 30, 0, 0);
  // Column 3 (label 0 in the exemplar) asked for label 1; column 7's label unknown; every
  // target altitude raised by 0.25 on row 0 only.
  for (int y = 0; y < 30; ++y) {
    a.labels[size_t(y) * 40 + 3] = 1;
    a.labels[size_t(y) * 40 + 7] = kUnknownLabel;
  }
  for (int x = 0; x < 40; ++x) a.altitude[size_t(x)] += 0.25f;
  const Metrics m = metrics(e, tally(e, a, a.rect, 1));
  EXPECT_DOUBLE_EQ(m.label_consistency, 1.0 - 30.0 / (1200 - 30));
  EXPECT_NEAR(m.altitude_mismatch, 0.25 * 40 / 1200, 1e-7);
}

TEST(AssessMetrics, OneRepeatedExcludedSource) {
  Exemplar e = noise_exemplar(20, 10, 3);
  const int32_t s = 2 * 20 + 13;
  e.excluded[size_t(s)] = 1;
  AssessedImage a;
  a.rect = {0, 0, 8, 5};
  for (int i = 0; i < 40; ++i) {
    for (size_t k = 0; k < 3; ++k) a.rgb.push_back(e.rgb[3 * size_t(s) + k]);
    a.source.push_back(i < 30 ? s : -1);  // 10 pixels without a source are not counted
    a.labels.push_back(1);
  }
  const Metrics m = metrics(e, tally(e, a, a.rect, 1));
  EXPECT_EQ(m.pixels, 30u);
  EXPECT_EQ(m.excluded_pixels, 30u);
  EXPECT_DOUBLE_EQ(m.distinct_source_fraction, 1.0 / 30);
  EXPECT_DOUBLE_EQ(m.max_source_share, 1.0);
  EXPECT_EQ(m.label_consistency, 1.0);
}

// The bounds of the distinct fraction: 40 allowed pixels of label 0 (60 excluded) and 100 of
// label 1; 50 output pixels of label 0, 20 of label 1 and 5 of none, all from one source. A
// synthesis keeping the labels draws at most 40 distinct for label 0, 20 for label 1 and 5
// anywhere: 65 of 75; the allowed pixels alone (140) would allow every one.
TEST(AssessMetrics, TheLabelBoundDrawsEachLabelFromItsOwnAllowedPixels) {
  Exemplar e = noise_exemplar(20, 10, 4);
  for (int y = 0; y < 6; ++y)
    for (int x = 0; x < 10; ++x) e.excluded[size_t(y * 20 + x)] = 1;
  AssessedImage a;
  a.rect = {0, 0, 75, 1};
  for (int i = 0; i < 75; ++i) {
    for (size_t k = 0; k < 3; ++k) a.rgb.push_back(e.rgb[3 * 199 + k]);
    a.source.push_back(199);
    a.labels.push_back(i < 50 ? 0 : i < 70 ? 1 : kUnknownLabel);
  }
  const Tally t = tally(e, a, a.rect, 1);
  EXPECT_EQ(t.labelled_by, (std::map<uint8_t, uint64_t>{{0, 50}, {1, 20}}));
  const Metrics m = metrics(e, t);
  EXPECT_DOUBLE_EQ(m.distinct_source_label_bound, 65.0 / 75);
  EXPECT_DOUBLE_EQ(m.distinct_source_bound, 1.0);
  EXPECT_DOUBLE_EQ(m.distinct_source_fraction, 1.0 / 75);
  // 100 more pixels of no label: only 140 - 60 allowed pixels are left for the 105 of them.
  a.rect.width = 175;
  for (int i = 0; i < 100; ++i) {
    for (size_t k = 0; k < 3; ++k) a.rgb.push_back(e.rgb[3 * 199 + k]);
    a.source.push_back(199);
    a.labels.push_back(kUnknownLabel);
  }
  const Metrics wide = metrics(e, tally(e, a, a.rect, 1));
  EXPECT_DOUBLE_EQ(wide.distinct_source_label_bound, 140.0 / 175);
  EXPECT_DOUBLE_EQ(wide.distinct_source_bound, 140.0 / 175);
}

TEST(AssessMetrics, CoherenceOfConstantColoursIsTheirSquaredDifferenceTimes75) {
  const Exemplar e = constant_exemplar(12, 12, 100);
  AssessedImage a;
  a.rect = {0, 0, 9, 7};
  a.rgb.assign(3 * 63, 110.0f);
  a.source.assign(63, -1);
  a.labels.assign(63, kUnknownLabel);
  a.rgb[3 * (3 * 9 + 8)] = NAN;  // (8, 3): its patches are not measured
  const Tally t = tally(e, a, a.rect, 1);
  // Patch centres (2..6) x (2..4), less those reaching (8, 3): centres 6 x 2..4 are 3 of 15.
  EXPECT_EQ(t.coherence_patches, 12u);
  EXPECT_DOUBLE_EQ(metrics(e, t).coherence, 75.0 * 10 * 10);
  // On a grid of step 2 (global columns and rows even): centres {2, 4, 6} x {2, 4}, less (6, 2)
  // and (6, 4).
  EXPECT_EQ(tally(e, a, a.rect, 2).coherence_patches, 4u);
}

TEST(AssessMetrics, CoherenceIsTheBruteForceNearestPatch) {
  const Exemplar e = noise_exemplar(24, 20, 4);
  const Exemplar other = noise_exemplar(16, 14, 99);  // unrelated colours
  AssessedImage a = copy_of(other, 0, 0, 16, 14, 3, 5);
  double sum = 0;
  int patches = 0;
  for (int y = 2; y < 12; ++y)
    for (int x = 2; x < 14; ++x) {
      double best = std::numeric_limits<double>::max();
      for (int ey = 2; ey < 18; ++ey)
        for (int ex = 2; ex < 22; ++ex) {
          double d = 0;
          for (int dy = -2; dy <= 2; ++dy)
            for (int dx = -2; dx <= 2; ++dx)
              for (size_t k = 0; k < 3; ++k) {
                const double u = other.rgb[3 * (size_t(y + dy) * 16 + size_t(x + dx)) + k];
                const double v = e.rgb[3 * (size_t(ey + dy) * 24 + size_t(ex + dx)) + k];
                d += (u - v) * (u - v);
              }
          best = std::min(best, d);
        }
      sum += best;
      ++patches;
    }
  const Tally t = tally(e, a, a.rect, 1);
  EXPECT_EQ(t.coherence_patches, uint64_t(patches));
  EXPECT_DOUBLE_EQ(t.coherence_sum, sum);
}

TEST(AssessMetrics, HistogramsOfKnownColours) {
  EXPECT_EQ(histogram_bin(31.4f, 0, 0), 0);
  EXPECT_EQ(histogram_bin(31.6f, 0, 0), 64);  // rounds to 32: red level 1
  EXPECT_EQ(histogram_bin(255, 0, 32), 7 * 64 + 1);
  // Exemplar label 0: half black, half white; label 1: all red.
  Exemplar e = noise_exemplar(8, 4, 5);
  for (size_t i = 0; i < 32; ++i) {
    const bool label0 = e.labels[i] == 0, white = i < 16;
    e.rgb[3 * i] = label0 ? (white ? 255.0f : 0.0f) : 200.0f;
    e.rgb[3 * i + 1] = e.rgb[3 * i + 2] = label0 && white ? 255.0f : 0.0f;
  }
  // Output: label 0 three quarters black, one quarter white (TV 0.25); label 1 all green
  // (TV 1); label 2 absent from the exemplar (1).
  AssessedImage a;
  a.rect = {0, 0, 10, 1};
  const auto add = [&](float r, float g, float b, uint8_t label) {
    a.rgb.insert(a.rgb.end(), {r, g, b});
    a.source.push_back(-1);
    a.labels.push_back(label);
  };
  for (int i = 0; i < 3; ++i) add(0, 0, 0, 0);
  add(255, 255, 255, 0);
  for (int i = 0; i < 4; ++i) add(0, 200, 0, 1);
  add(9, 9, 9, 2);
  add(9, 9, 9, kUnknownLabel);  // not in any histogram
  const Metrics m = metrics(e, tally(e, a, a.rect, 1));
  ASSERT_EQ(m.histogram_distance.size(), 3u);
  EXPECT_DOUBLE_EQ(m.histogram_distance.at(0), 0.25);
  EXPECT_DOUBLE_EQ(m.histogram_distance.at(1), 1.0);
  EXPECT_DOUBLE_EQ(m.histogram_distance.at(2), 1.0);
  EXPECT_DOUBLE_EQ(m.worst_histogram_distance, 1.0);
  // Excluded exemplar pixels are not the label's colours: the white ones out, label 0 all black.
  for (size_t i = 0; i < 16; ++i) e.excluded[i] = 1;
  EXPECT_DOUBLE_EQ(metrics(e, tally(e, a, a.rect, 1)).histogram_distance.at(0), 0.25);
  EXPECT_DOUBLE_EQ(total_variation(exemplar_histogram(e, 0), {}), 1.0);
}

TEST(AssessMetrics, WindowsMergedEqualTheWhole) {
  const Exemplar e = noise_exemplar(40, 30, 6);
  AssessedImage a = copy_of(e, 2, 1, 36, 28, 64, 64);
  for (size_t i = 0; i < a.source.size(); i += 7) a.source[i] = int32_t(i % 50);  // repeats
  for (size_t i = 0; i < a.rgb.size(); i += 11) a.rgb[i] += 40;                   // incoherence
  const Tally whole = tally(e, a, a.rect, 1);
  Tally merged;
  for (const PixelRect part :
       {PixelRect{64, 64, 20, 28}, PixelRect{84, 64, 16, 10}, PixelRect{84, 74, 16, 18}})
    merged.merge(tally(e, a, part, 1));
  EXPECT_EQ(merged.pixels, whole.pixels);
  EXPECT_EQ(merged.uses, whole.uses);
  EXPECT_EQ(merged.labelled_by, whole.labelled_by);
  EXPECT_EQ(merged.histograms, whole.histograms);
  EXPECT_EQ(merged.coherence_patches, whole.coherence_patches);
  EXPECT_NEAR(merged.coherence_sum, whole.coherence_sum, 1e-9 * whole.coherence_sum);
  const Metrics m = metrics(e, whole);
  EXPECT_GT(m.coherence, 0.0);
  EXPECT_LT(m.distinct_source_fraction, 1.0);
}

}  // namespace
}  // namespace maquette::synthesis
