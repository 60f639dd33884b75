// Issue 18's measures of a transfer: how well an output, and the exemplar pixels it was copied
// from, keep the target's labels, avoid the exclusion mask, stay coherent and avoid repetition.
// They read only colours, source pixels and labels, so any synthesis (ebsynth's, through its
// nearest-neighbour field) is scored the same way.
//
// A measurement is split into a Tally of one window (sums and counts, merged over windows in any
// grouping with the same result) and the Metrics computed from the merged Tally and the exemplar,
// so that a reduce operator can tally cell by cell.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

#include "exemplar.h"
#include "exemplar_pyramid.h"
#include "synthesis.h"

namespace maquette::synthesis {

inline constexpr int kCoherenceRadius = 2;  // coherence patches of 5 x 5 pixels
inline constexpr int kCoherenceSide = 2 * kCoherenceRadius + 1;
inline constexpr int kHistogramBins = 8 * 8 * 8;  // RGB, 32 levels per bin and channel

// An output image over a rectangle of global pixels, row-major, rect.width x rect.height.
struct AssessedImage {
  PixelRect rect;
  std::vector<float> rgb;       // 3 per pixel, 0..255; NaN: no output here
  std::vector<int32_t> source;  // exemplar pixel y * width + x it was copied from; -1: none
  std::vector<uint8_t> labels;  // target label (painting class), kUnknownLabel: none
  std::vector<float> altitude;  // target altitude [0, 1] (NaN: none), or empty
};

// Sums and counts of one window; merge() adds another window's.
struct Tally {
  uint64_t pixels = 0;                      // output pixels with a source
  uint64_t labelled = 0;                    // of which with a known target label
  uint64_t label_matches = 0;               // of which whose source has that label
  std::map<uint8_t, uint64_t> labelled_by;  // the labelled ones by target label
  uint64_t excluded = 0;                    // pixels with a source in the exclusion mask
  double coherence_sum = 0;                 // sum of the nearest exemplar patches' SSD
  uint64_t coherence_patches = 0;
  double altitude_sum = 0;  // sum of |target altitude - source altitude|
  uint64_t altitude_pixels = 0;
  std::map<int32_t, uint64_t> uses;  // exemplar pixel -> output pixels copied from it
  // Target label -> the output colours of its pixels, kHistogramBins counts (histogram_bin).
  std::map<uint8_t, std::vector<uint64_t>> histograms;

  void merge(const Tally& other);
};

struct Metrics {
  uint64_t pixels = 0;
  double label_consistency = 0;  // label_matches / labelled (1 when none is labelled)
  uint64_t excluded_pixels = 0;
  // Mean over output patches of the SSD to the nearest exemplar patch: 5 x 5 pixels x RGB,
  // 0..255 units (so 25 x 3 squared differences per patch).
  double coherence = 0;
  double distinct_source_fraction = 0;  // distinct source pixels / pixels
  uint64_t allowed_pixels = 0;          // the exemplar's (not excluded)
  // The most the fraction can be: the exemplar's allowed pixels over the pixels (at most 1);
  // and the most for a synthesis that keeps every pixel's label, each label's pixels drawing on
  // the allowed pixels of that label (the pixels of no label on any left), over the pixels.
  double distinct_source_bound = 0, distinct_source_label_bound = 0;
  double max_source_share = 0;  // most used source pixel's uses / pixels
  // Per target label, total variation 0.5 sum |p - q| between the bin frequencies of the output
  // colours of its pixels and of the exemplar's allowed pixels of that label (1 when the
  // exemplar has none); and the worst of them.
  std::map<uint8_t, double> histogram_distance;
  double worst_histogram_distance = 0;
  double altitude_mismatch = 0;  // mean |target - source altitude| (0 when none)
};

// A transfer's exemplar as its output copies it (the pyramid's finest level): colours 0..255
// rounded to the 8-bit values synthesis.transfer writes, labels, altitude and exclusion as they
// are.
Exemplar copied_exemplar(const ExemplarLevel& finest);

// The 8 x 8 x 8 bin of a colour 0..255: each channel rounded to an integer, then / 32.
int histogram_bin(float r, float g, float b);

// The Tally of the pixels of `image` inside `counted` (global coordinates within image.rect),
// against exemplar `e` (colours 0..255, labels, altitude, exclusion; sources index its pixels).
// Coherence: every counted pixel whose global column and row are multiples of `coherence_step`
// and whose 5 x 5 patch lies in image.rect with all colours known, against every exemplar patch
// inside the exemplar whose centre is not excluded: an exact nearest-neighbour search (a k-d
// tree) on colours alone. So the image's margin around `counted` (kCoherenceRadius) is read for
// coherence only. Preconditions: the vectors have image.rect's pixels (altitude may be empty),
// sources are -1 or exemplar pixels, `counted` lies in image.rect, coherence_step >= 1.
Tally tally(const Exemplar& e, const AssessedImage& image, const PixelRect& counted,
            int coherence_step);

// The most distinct sources output pixels can have while each keeps its label: `labelled` of
// each target label drawing on the allowed pixels of exemplar `e` of that label, `unlabelled`
// ones on the allowed pixels left.
uint64_t label_keeping_sources(const Exemplar& e, const std::map<uint8_t, uint64_t>& labelled,
                               uint64_t unlabelled);

// The Metrics of a (merged) Tally against the exemplar it was tallied on.
Metrics metrics(const Exemplar& e, const Tally& t);

// The exemplar's histogram of label `label` (its allowed pixels), kHistogramBins counts.
std::vector<uint64_t> exemplar_histogram(const Exemplar& e, uint8_t label);

// Total variation distance between the frequencies of two histograms of the same bins, as counts
// or weights (1 when either is empty).
template <typename Count>
double total_variation(const std::vector<Count>& a, const std::vector<Count>& b) {
  Count na = 0, nb = 0;
  for (const Count n : a) na += n;
  for (const Count n : b) nb += n;
  if (na == 0 || nb == 0) return 1;
  double d = 0;
  for (size_t i = 0; i < a.size(); ++i)
    d += std::abs(double(a[i]) / double(na) - double(b[i]) / double(nb));
  return d / 2;
}

}  // namespace maquette::synthesis
