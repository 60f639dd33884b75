// The parallel synthesis (synthesis.h) on a synthetic two-class exemplar: windows computed with
// their halo equal the whole image's crop (64^2 and 128^2 tiles, the guides cut to each window
// and its halo), on one thread and two; no excluded pixel is ever copied; sources keep the
// target's labels; the output is the vote of the copy, and the vote smooths the colours of
// neighbours; the patch passes keep the tiles equal and lower the coherence; the wanted pixels
// computed alone are the same bits; strong block preferences with spread_typical keep off the
// atypical regions; guides that miss the halo, a vote radius outside 0 .. kVoteRadius and patch
// passes or draws outside their ranges are refused.
#include "../synthesis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <thread>
#include <utility>

#include "../assess_metrics.h"
#include "../exemplar_usage.h"
#include "../patch_pass.h"
#include "../pixel_hash.h"
#include "../vote.h"
#include "core/error.h"
#include "painted_exemplar.h"

namespace maquette::synthesis {
namespace {

// Left half label 0 (warm stripes), right half label 1 (green blobs), each with an excluded
// magenta square; altitude rising from bottom to top.
Exemplar two_class_exemplar() {
  return test::painted_exemplar(128, 96, true, [](Exemplar& e, int x, int y, size_t i) {
    const float noise = float(splitmix64_mix(i) % 41) - 20.0f;
    const bool right = x >= e.width / 2;
    e.labels[i] = right ? 1 : 0;
    const bool hole =
        (x >= 20 && x < 32 && y >= 40 && y < 52) || (x >= 90 && x < 102 && y >= 10 && y < 22);
    e.excluded[i] = hole;
    e.altitude[i] = 1.0f - float(y) / float(e.height - 1);
    const float r = hole    ? 255
                    : right ? 40 + 30 * std::sin(x * 0.7f) * std::sin(y * 0.6f) + noise
                            : 200 + 40 * std::sin(x / 3.0f) + noise;
    const float g = hole ? 0 : right ? 110 + noise : 170 + noise;
    const float b = hole ? 255 : right ? 50 : 60 + noise;
    e.rgb[3 * i] = r, e.rgb[3 * i + 1] = g, e.rgb[3 * i + 2] = b;
  });
}

constexpr PixelRect kWhole{4096 + 7, 37, 256, 256};

// Label 1 inside a disc, 0 outside, unknown in a band; altitude a ramp. Over `rect`.
TargetGuides guides(const PixelRect& rect) {
  TargetGuides g{rect,
                 0,
                 std::vector<uint8_t>(size_t(rect.width) * size_t(rect.height)),
                 std::vector<float>(size_t(rect.width) * size_t(rect.height)),
                 {},
                 {},
                 {}};
  for (int64_t r = 0; r < rect.height; ++r)
    for (int64_t c = 0; c < rect.width; ++c) {
      const double x = double(rect.col0 + c - kWhole.col0 - 128),
                   y = double(rect.row0 + r - kWhole.row0 - 128);
      const size_t i = size_t(r) * size_t(rect.width) + size_t(c);
      g.labels[i] = std::abs(x - 40) < 3 ? kUnknownLabel : x * x + y * y < 80.0 * 80.0 ? 1 : 0;
      g.altitude[i] = float(std::clamp(0.5 - y / 400.0, 0.0, 1.0));
    }
  return g;
}

// The most patch passes, balanced, with the most draws around the source and from class edges.
SynthesisParams every_patch_pass() {
  SynthesisParams p;
  p.patch_passes = kMaxPatchPasses;
  p.patch_balance = 0.25;
  p.patch_search = kMaxPatchSearch;
  p.patch_edges = kMaxPatchEdges;
  return p;
}

PixelRect grown(const PixelRect& r, int m) {
  return {r.col0 - m, r.row0 - m, r.width + 2 * m, r.height + 2 * m};
}

class SynthesisTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    exemplar_ = new Exemplar(two_class_exemplar());
    pyramid_ = new ExemplarPyramid(analyse_exemplar(*exemplar_, kLevels, 2));
    measure_usage(*pyramid_, {});
    whole_ = new std::vector<int32_t>(
        synthesize(*pyramid_, guides(grown(kWhole, synthesis_halo())), {}, kWhole));
  }
  static void TearDownTestSuite() {
    delete exemplar_;
    delete pyramid_;
    delete whole_;
  }

  // The tiles of `side` computed on `threads` threads with `params`, pasted into one image.
  static std::vector<int32_t> tiled(int side, int threads, const SynthesisParams& params = {}) {
    std::vector<int32_t> out(whole_->size(), -1);
    const int per_row = int(kWhole.width / side), count = per_row * int(kWhole.height / side);
    const auto work = [&](int first) {
      for (int t = first; t < count; t += threads) {
        const PixelRect tile{kWhole.col0 + (t % per_row) * side, kWhole.row0 + (t / per_row) * side,
                             side, side};
        const auto src = synthesize(*pyramid_, guides(grown(tile, synthesis_halo())), params, tile);
        for (int r = 0; r < side; ++r)
          for (int c = 0; c < side; ++c)
            out[size_t(tile.row0 - kWhole.row0 + r) * size_t(kWhole.width) +
                size_t(tile.col0 - kWhole.col0 + c)] = src[size_t(r) * size_t(side) + size_t(c)];
      }
    };
    std::vector<std::thread> pool;
    for (int i = 0; i < threads; ++i) pool.emplace_back(work, i);
    for (std::thread& t : pool) t.join();
    return out;
  }

  static size_t differing(const std::vector<int32_t>& a, const std::vector<int32_t>& b) {
    size_t n = 0;
    for (size_t i = 0; i < a.size(); ++i) n += a[i] != b[i];
    return n;
  }

  static inline Exemplar* exemplar_ = nullptr;
  static inline ExemplarPyramid* pyramid_ = nullptr;
  static inline std::vector<int32_t>* whole_ = nullptr;
};

TEST_F(SynthesisTest, TilesWithTheirHaloEqualTheWholeImage) {
  EXPECT_EQ(differing(tiled(64, 1), *whole_), 0u);
  EXPECT_EQ(differing(tiled(128, 1), *whole_), 0u);
}

TEST_F(SynthesisTest, AShiftedOddWindowEqualsTheWholeImage) {
  const PixelRect window{kWhole.col0 + 37, kWhole.row0 + 53, 101, 67};
  const auto src = synthesize(*pyramid_, guides(grown(window, synthesis_halo())), {}, window);
  size_t differing = 0;
  for (int64_t r = 0; r < window.height; ++r)
    for (int64_t c = 0; c < window.width; ++c)
      differing +=
          src[size_t(r * window.width + c)] != (*whole_)[size_t((r + 53) * kWhole.width + c + 37)];
  EXPECT_EQ(differing, 0u);
}

TEST_F(SynthesisTest, SameBitsOnTwoThreads) { EXPECT_EQ(differing(tiled(64, 2), *whole_), 0u); }

// The widest vote with the histogram balance (vote.h: the colour excess measured on the
// exemplar) keeps the output a function of global pixel coordinates, and the balance changes it.
TEST_F(SynthesisTest, TheBalancedVoteOfRadius2TilesEqualTheWholeImage) {
  SynthesisParams balanced;
  balanced.vote_radius = 2;
  balanced.vote_balance = 1;
  const auto whole =
      synthesize(*pyramid_, guides(grown(kWhole, synthesis_halo())), balanced, kWhole);
  EXPECT_EQ(differing(tiled(64, 2, balanced), whole), 0u);
  EXPECT_EQ(differing(tiled(128, 1, balanced), whole), 0u);
  SynthesisParams unbalanced = balanced;
  unbalanced.vote_balance = 0;
  EXPECT_GT(
      differing(synthesize(*pyramid_, guides(grown(kWhole, synthesis_halo())), unbalanced, kWhole),
                whole),
      whole.size() / 100);
}

// The patch passes (patch_pass.h), the most of them, balanced, searching and drawing from the
// exemplar's class edges, keep the output a
// function of global pixel coordinates (their reach is in the halo), change it, and lower its
// coherence (synthesis.assess's: the SSD of each 5 x 5 output patch to its nearest exemplar patch).
TEST_F(SynthesisTest, PatchPassesKeepTilesEqualToTheWholeImageAndLowerTheCoherence) {
  SynthesisParams passed = every_patch_pass();
  ASSERT_FALSE(pyramid_->levels[0].class_edges.empty());
  passed.line_classes.set(1);  // its thin pixels keep their sources: a function of the labels too
  const TargetGuides target = guides(grown(kWhole, synthesis_halo()));
  const auto whole = synthesize(*pyramid_, target, passed, kWhole);
  EXPECT_EQ(differing(tiled(64, 2, passed), whole), 0u);
  EXPECT_EQ(differing(tiled(128, 1, passed), whole), 0u);
  const PixelRect window{kWhole.col0 + 37, kWhole.row0 + 53, 101, 67};
  const auto shifted =
      synthesize(*pyramid_, guides(grown(window, synthesis_halo())), passed, window);
  size_t moved = 0;
  for (int64_t r = 0; r < window.height; ++r)
    for (int64_t c = 0; c < window.width; ++c)
      moved +=
          shifted[size_t(r * window.width + c)] != whole[size_t((r + 53) * kWhole.width + c + 37)];
  EXPECT_EQ(moved, 0u);
  const Exemplar copied = copied_exemplar(pyramid_->levels[0]);
  const TargetGuides labels = guides(kWhole);
  const auto coherence = [&](const std::vector<int32_t>& src) {
    AssessedImage image{kWhole, std::vector<float>(3 * src.size()), src, labels.labels, {}};
    for (size_t i = 0; i < src.size(); ++i)
      for (size_t k = 0; k < 3; ++k) image.rgb[3 * i + k] = copied.rgb[3 * size_t(src[i]) + k];
    return metrics(copied, tally(copied, image, kWhole, 4)).coherence;
  };
  EXPECT_GT(differing(whole, *whole_), whole.size() / 10);
  EXPECT_LT(coherence(whole), 0.9 * coherence(*whole_));
}

// Only the wanted pixels kept (synthesis_plan.h: the land where the land cover has no data
// around it): they are the whole image's bits, with every pass, draw and the widest vote, and
// scattered single pixels (cones at every parity and offset) under a strong reuse penalty; the
// others were not computed (many differ from the whole image's).
TEST_F(SynthesisTest, WantedPixelsAloneAreTheWholeImagesBits) {
  SynthesisParams passed = every_patch_pass();
  passed.vote_radius = kVoteRadius;
  SynthesisParams reused;
  reused.w_repetition = 4;
  const TargetGuides target = guides(grown(kWhole, synthesis_halo()));
  // A half-disc on the left, a line of pixels and one pixel apart; one pixel in 61, scattered.
  std::vector<uint8_t> shapes(size_t(kWhole.width * kWhole.height)), scattered(shapes.size());
  for (int64_t r = 0; r < kWhole.height; ++r)
    for (int64_t c = 0; c < kWhole.width; ++c) {
      const size_t i = size_t(r * kWhole.width + c);
      shapes[i] = (c < 128 && (c - 128) * (c - 128) + (r - 128) * (r - 128) < 70 * 70) ||
                  (r == 17 && c > 140) || (r == 230 && c == 200);
      scattered[i] = splitmix64_mix(i) % 61 == 0;
    }
  // The kept pixels' differences from the whole image (none expected), and the others'.
  const auto differences = [&](const SynthesisParams& params, const std::vector<uint8_t>& wanted) {
    const auto whole = synthesize(*pyramid_, target, params, kWhole);
    const auto kept = synthesize(*pyramid_, target, params, kWhole, wanted);
    std::array<size_t, 2> n{};
    for (size_t i = 0; i < whole.size(); ++i) n[wanted[i] ? 0 : 1] += kept[i] != whole[i];
    return n;
  };
  const auto [wrong, other] = differences(passed, shapes);
  EXPECT_EQ(wrong, 0u);
  EXPECT_GT(other, shapes.size() / 4);
  EXPECT_EQ(differences(reused, scattered)[0], 0u);
  EXPECT_THROW(synthesize(*pyramid_, target, passed, kWhole, std::vector<uint8_t>(7, 1)), Error);
}

TEST_F(SynthesisTest, NeverCopiesAnExcludedPixel) {
  size_t excluded = 0;
  for (const int32_t s : *whole_) {
    ASSERT_GE(s, 0);
    excluded += exemplar_->excluded[size_t(s)];
  }
  EXPECT_EQ(excluded, 0u);
}

TEST_F(SynthesisTest, SourcesKeepTheTargetLabels) {
  const TargetGuides g = guides(kWhole);
  size_t known = 0, kept = 0;
  for (size_t i = 0; i < whole_->size(); ++i) {
    if (g.labels[i] == kUnknownLabel) continue;
    ++known;
    kept += exemplar_->labels[size_t((*whole_)[i])] == g.labels[i];
  }
  // Both labels have allowed exemplar pixels: every pixel ends on one of its own label.
  EXPECT_EQ(kept, known);
}

TEST_F(SynthesisTest, CopiesPatchesNotScatteredPixels) {
  // Coherence: most horizontal neighbours come from horizontally adjacent exemplar pixels.
  size_t coherent = 0, pairs = 0;
  for (int64_t r = 0; r < kWhole.height; ++r)
    for (int64_t c = 0; c + 1 < kWhole.width; ++c, ++pairs) {
      const int32_t a = (*whole_)[size_t(r * kWhole.width + c)],
                    b = (*whole_)[size_t(r * kWhole.width + c + 1)];
      coherent += b == a + 1;
    }
  // Sources drawn at random would be adjacent for ~1 pair in 10^4.
  EXPECT_GE(double(coherent) / double(pairs), 0.2);
}

// The output is the vote (vote.h, tested on hand-built cases in vote_test.cpp) of the copy
// without one: the state the vote reads is a window without a vote, grown by the vote's radius.
TEST_F(SynthesisTest, TheOutputIsTheVoteOfTheCopy) {
  const PixelRect window{kWhole.col0 + 64, kWhole.row0 + 64, 128, 128};
  const PixelRect around = grown(window, kVoteRadius);
  SynthesisParams copy;
  copy.vote_radius = 0;
  const auto state = synthesize(*pyramid_, guides(grown(around, synthesis_halo())), copy, around);
  const TargetGuides g = guides(around);
  const auto expected = vote(pyramid_->levels[0], {around, state, around, g.labels, {}, 1.05},
                             SynthesisParams{}.vote_radius, window);
  const auto voted = synthesize(*pyramid_, guides(grown(window, synthesis_halo())), {}, window);
  EXPECT_EQ(differing(voted, expected), 0u);
  // The vote does change the copy.
  size_t moved = 0;
  for (int64_t r = 0; r < window.height; ++r)
    for (int64_t c = 0; c < window.width; ++c)
      moved += voted[size_t(r * window.width + c)] !=
               state[size_t((r + kVoteRadius) * around.width + c + kVoteRadius)];
  EXPECT_GT(moved, size_t(window.width * window.height / 20));
}

TEST_F(SynthesisTest, TheVoteSmoothsTheColoursOfNeighbours) {
  // Mean squared colour difference of horizontal neighbours, with and without the vote.
  const ExemplarLevel& e = pyramid_->levels[0];
  const auto roughness = [&](const std::vector<int32_t>& src) {
    double sum = 0;
    for (int64_t r = 0; r < kWhole.height; ++r)
      for (int64_t c = 0; c + 1 < kWhole.width; ++c)
        for (size_t k = 0; k < 3; ++k)
          sum += std::pow(e.rgb[3 * size_t(src[size_t(r * kWhole.width + c + 1)]) + k] -
                              e.rgb[3 * size_t(src[size_t(r * kWhole.width + c)]) + k],
                          2);
    return sum;
  };
  SynthesisParams copy;
  copy.vote_radius = 0;
  const auto without = synthesize(*pyramid_, guides(grown(kWhole, synthesis_halo())), copy, kWhole);
  EXPECT_LT(roughness(*whole_), 0.9 * roughness(without));
}

// The exemplar's measured over-use (exemplar_usage.h) and the blocks' preferences spread the
// copies: against the synthesis without them, more sources are used (8,480 against 7,423 here),
// the most used one no more.
TEST_F(SynthesisTest, UsageAndSpreadUseMoreSources) {
  const auto uses = [](const std::vector<int32_t>& src) {
    std::map<int32_t, size_t> count;
    for (const int32_t s : src) ++count[s];
    size_t most = 0;
    for (const auto& [s, n] : count) most = std::max(most, n);
    return std::pair{most, count.size()};
  };
  SynthesisParams plain;
  plain.w_usage = plain.w_spread = 0;
  const auto [most_plain, distinct_plain] =
      uses(synthesize(*pyramid_, guides(grown(kWhole, synthesis_halo())), plain, kWhole));
  const auto [most, distinct] = uses(*whole_);
  EXPECT_GT(double(distinct), 1.1 * double(distinct_plain));
  EXPECT_LE(most, most_plain);
}

// With strong block preferences, spread_typical 0.6 keeps the blocks off the regions outside the
// central 60 % of their class by lightness (spread_regions.h): 40 % of each class's allowed
// pixels, which with every region preferable supply about as large a share of the output; the
// colours still call for some of them.
TEST_F(SynthesisTest, BlocksPreferNoRegionOutsideTheTypicalShare) {
  const std::vector<uint8_t>& quantile = pyramid_->levels[0].region_quantile;
  const auto atypical_share = [&](double spread_typical) {
    SynthesisParams p;
    p.w_spread = 8;
    p.spread_typical = spread_typical;
    const auto src = synthesize(*pyramid_, guides(grown(kWhole, synthesis_halo())), p, kWhole);
    size_t n = 0;
    for (const int32_t s : src) n += !typical_region(quantile[size_t(s)], 0.6);
    return double(n) / double(src.size());
  };
  const double every = atypical_share(1.0), typical = atypical_share(0.6);
  std::printf("sources in atypical regions: %.3f with every region preferable, %.3f without\n",
              every, typical);
  EXPECT_GT(every, 0.25);
  EXPECT_LT(typical, 0.5 * every);
}

TEST_F(SynthesisTest, RaisingTheAltitudeWeightLowersTheAltitudeMismatch) {
  const PixelRect window{kWhole.col0 + 64, kWhole.row0 + 64, 128, 128};
  const TargetGuides target = guides(grown(window, synthesis_halo()));
  double previous = 1.0;
  for (const double weight : {0.0, 2.0, 8.0}) {
    SynthesisParams params;
    params.w_altitude = weight;
    const auto src = synthesize(*pyramid_, target, params, window);
    double mismatch = 0;
    for (int64_t r = 0; r < window.height; ++r)
      for (int64_t c = 0; c < window.width; ++c) {
        const size_t t =
            size_t(r + synthesis_halo()) * size_t(target.rect.width) + size_t(c + synthesis_halo());
        mismatch +=
            std::abs(double(target.altitude[t]) -
                     double(exemplar_->altitude[size_t(src[size_t(r * window.width + c)])]));
      }
    mismatch /= double(src.size());
    EXPECT_LT(mismatch, previous) << "w_altitude " << weight;
    previous = mismatch;
  }
}

// synthesis_halo() is the widest reach, that of the most patch passes.
TEST_F(SynthesisTest, RefusesGuidesWithoutTheHalo) {
  SynthesisParams passed;
  passed.patch_passes = kMaxPatchPasses;
  EXPECT_THROW(synthesize(*pyramid_, guides(grown(kWhole, synthesis_halo() - 8)), passed, kWhole),
               Error);
}

TEST_F(SynthesisTest, RefusesAVoteRadiusOutsideItsRange) {
  const TargetGuides target = guides(grown(kWhole, synthesis_halo()));
  for (const int radius : {-1, kVoteRadius + 1}) {
    SynthesisParams params;
    params.vote_radius = radius;
    try {
      synthesize(*pyramid_, target, params, kWhole);
      ADD_FAILURE() << "vote_radius " << radius << " accepted";
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()), "synthesis: vote_radius " + std::to_string(radius) +
                                           ": must be 0 .. " + std::to_string(kVoteRadius));
    }
  }
  for (const int radius : {0, kVoteRadius}) {
    SynthesisParams params;
    params.vote_radius = radius;
    EXPECT_NO_THROW(synthesize(*pyramid_, target, params, kWhole)) << "vote_radius " << radius;
  }
}

TEST_F(SynthesisTest, RefusesPatchPassesOrDrawsOutsideTheirRange) {
  const TargetGuides target = guides(grown(kWhole, synthesis_halo()));
  const auto refused = [&](const SynthesisParams& params, const std::string& message) {
    try {
      synthesize(*pyramid_, target, params, kWhole);
      ADD_FAILURE() << "accepted: " << message;
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()), message);
    }
  };
  for (const int n : {-1, kMaxPatchPasses + 1}) {
    SynthesisParams params;
    params.patch_passes = n;
    refused(params, "synthesis: patch_passes " + std::to_string(n) + ": must be 0 .. " +
                        std::to_string(kMaxPatchPasses));
  }
  for (const int n : {-1, kMaxPatchSearch + 1}) {
    SynthesisParams params;
    params.patch_search = n;
    refused(params, "synthesis: patch_search " + std::to_string(n) + ": must be 0 .. " +
                        std::to_string(kMaxPatchSearch));
  }
  for (const int n : {-1, kMaxPatchEdges + 1}) {
    SynthesisParams params;
    params.patch_edges = n;
    refused(params, "synthesis: patch_edges " + std::to_string(n) + ": must be 0 .. " +
                        std::to_string(kMaxPatchEdges));
  }
}

}  // namespace
}  // namespace maquette::synthesis
