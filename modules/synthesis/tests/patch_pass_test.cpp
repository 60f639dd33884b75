// The finest level's patch pass (patch_pass.h) on a hand-built window whose answers are worked
// out here: the proposal whose 5 x 5 patch fits the output beats the majority and the pixel's own
// source; proposals of another label, excluded, or whose patch leaves the exemplar are ignored
// (ties then go to the first in row-major order); a depth break and the other parities keep the
// pixel's source, and so does a pixel of a line class thinner than its window; the histogram
// balance weighs each proposal by its colour excess; places drawn around the source, and from the
// exemplar's edges between the two classes, compete where the target's classes meet, and only
// there.
#include "../patch_pass.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <limits>
#include <tuple>
#include <utility>

#include "../class_edges.h"

namespace maquette::synthesis {
namespace {

constexpr int kSide = 40;

// A grey exemplar of kSide x kSide pixels (0.5), label 0, nothing excluded, but for the marked
// pixels below.
//
// The window of radius 2 around output pixel (0, 0) copies A's neighbourhood, S(d) = A + d, but
// for its own pixel, S(0) = C, and its right neighbour, S(1, 0) = B + (1, 0). So A is proposed by
// 23 neighbours (the first of them d = (-2, -2)), B and C once each, and the output's colours
// are 0.5 everywhere (its centre left out). Against it, A's patch differs at (1, 0), where (11, 10)
// is 0, by 0.5 (SSD 3 x 0.25 = 0.75); C's at (-1, 0), where (9, 30) is 1, by 0.5 (0.75); B's at
// (1, 1), where (31, 31) is 0.3, by 0.2 (0.12). B wins. Any other place whose patch holds no
// marked pixel fits exactly (0).
constexpr std::pair<int, int> kA{10, 10}, kB{30, 30}, kC{10, 30};

ExemplarLevel exemplar() {
  ExemplarLevel e;
  e.width = e.height = kSide;
  e.rgb.assign(3 * kSide * kSide, 0.5f);
  e.labels.assign(kSide * kSide, 0);
  e.excluded.assign(kSide * kSide, 0);
  for (const auto& [x, y, grey] : {std::tuple{11, 10, 0.0f}, {9, 30, 1.0f}, {31, 31, 0.3f}})
    for (size_t k = 0; k < 3; ++k) e.rgb[3 * size_t(e.index(x, y)) + k] = grey;
  return e;
}

int32_t at(std::pair<int, int> xy) { return xy.second * kSide + xy.first; }

constexpr PixelRect kPixel{0, 0, 1, 1};
constexpr PixelRect kWindow{-2, -2, 5, 5};

std::vector<int32_t> window_state(std::pair<int, int> b = kB) {
  std::vector<int32_t> state(25);
  for (int i = 0; i < 25; ++i) {
    const int dx = i % 5 - 2, dy = i / 5 - 2;
    const auto [x, y] = dx == 0 && dy == 0 ? kC : dx == 1 && dy == 0 ? b : kA;
    state[size_t(i)] = (y + dy) * kSide + x + dx;
  }
  return state;
}

// The sub-pass's winner at pixel (0, 0), the target's altitude `altitude` throughout (none when
// empty) weighed by w_altitude.
int32_t passed_with_altitude(const ExemplarLevel& e, const std::vector<int32_t>& state,
                             const std::vector<float>& altitude, double w_altitude,
                             const std::vector<float>& depth = {}, double balance = 0, int px = 0,
                             const std::vector<uint8_t>& labels = std::vector<uint8_t>(25, 0),
                             int search = 0, int edges = 0) {
  return patch_sub_pass(
             e, {kWindow, labels, depth, altitude, 1.05, balance, search, edges, w_altitude, 0, 0},
             kWindow, state, kPixel, px, 0, 64)
      .at(0);
}

int32_t passed(const ExemplarLevel& e, const std::vector<int32_t>& state,
               const std::vector<float>& depth = {}, double balance = 0, int px = 0,
               const std::vector<uint8_t>& labels = std::vector<uint8_t>(25, 0), int search = 0,
               int edges = 0) {
  return passed_with_altitude(e, state, {}, 0, depth, balance, px, labels, search, edges);
}

TEST(PatchPass, TheProposalWhosePatchFitsBestWinsNotTheMajorityNorTheOwnSource) {
  EXPECT_EQ(passed(exemplar(), window_state()), at(kB));
}

TEST(PatchPass, IgnoresProposalsOfAnotherLabelExcludedOrWhosePatchLeavesTheExemplar) {
  ExemplarLevel e = exemplar();
  e.labels[size_t(at(kB))] = 1;
  EXPECT_EQ(passed(e, window_state()), at(kA));  // A and C tie: A is proposed first
  e = exemplar();
  e.excluded[size_t(at(kB))] = 1;
  EXPECT_EQ(passed(e, window_state()), at(kA));
  // B at column 1: its patch would read column -1.
  e = exemplar();
  EXPECT_EQ(passed(e, window_state({1, 20})), at(kA));
  // Every proposal ignored: the pixel keeps its source.
  e.labels.assign(e.labels.size(), 1);
  EXPECT_EQ(passed(e, window_state()), at(kC));
}

TEST(PatchPass, ADepthBreakOrAnotherParityKeepsTheSource) {
  const ExemplarLevel e = exemplar();
  std::vector<float> depth(25, 100.0f);
  EXPECT_EQ(passed(e, window_state(), depth), at(kB));
  depth[24] = 200.0f;  // (2, 2) twice as far
  EXPECT_EQ(passed(e, window_state(), depth), at(kC));
  depth[24] = std::numeric_limits<float>::infinity();  // the sky
  EXPECT_EQ(passed(e, window_state(), depth), at(kC));
  EXPECT_EQ(passed(e, window_state(), {}, 0, 1), at(kC));  // columns of parity 1 only
}

// With B's colour over-shown 4 times and A's under-shown (0.25): B's (0.12 + 24 floors) x 4 =
// 0.4896 against A's (0.75 + 24 floors) x 0.25 = 0.1881 and C's (1 excess) 0.7524: A wins; with
// no excess measured, or balance 0, B.
// A line class (line_classes) thinner than the window keeps its source: with 13 of the window's
// 25 pixels of another label p (label 0) keeps C when 0 is a line class, and takes B when it is
// not or when 0 holds a strict majority (13 of 25).
TEST(PatchPass, APixelOfALineClassThinnerThanItsWindowKeepsItsSource) {
  const ExemplarLevel e = exemplar();
  std::vector<uint8_t> labels(25, 0);
  for (size_t i = 0; i < 12; ++i) labels[i] = 1;  // the first two rows and two more
  const auto winner = [&](bool line) {
    PatchPassInputs in{kWindow, labels, {}, {}, 1.05, 0, 0, 0, 0, 0, 0};
    in.line_classes.set(0, line);
    return patch_sub_pass(e, in, kWindow, window_state(), kPixel, 0, 0, 64).at(0);
  };
  EXPECT_EQ(winner(true), at(kB));  // 13 of 25: a strict majority
  labels[13] = 1;                   // (1, 0): 12 of 25
  EXPECT_EQ(winner(true), at(kC));
  EXPECT_EQ(winner(false), at(kB));
}

TEST(PatchPass, TheBalanceWeighsEachProposalByItsColoursExcess) {
  ExemplarLevel e = exemplar();
  EXPECT_EQ(passed(e, window_state(), {}, 1), at(kB));  // no excess measured
  e.colour_excess.assign(e.labels.size(), 1.0f);
  e.colour_excess[size_t(at(kB))] = 4;
  e.colour_excess[size_t(at(kA))] = 0.25f;
  EXPECT_EQ(passed(e, window_state(), {}, 1), at(kA));
  EXPECT_EQ(passed(e, window_state(), {}, 0), at(kB));
  EXPECT_EQ(passed(e, window_state(), {}, 0.1), at(kB));  // 0.12 x 1.149 < 0.75 x 0.871
}

// The search draws places around C only where the target's classes meet: with a pixel of
// another label in the window, a drawn place (within 16 of C, its patch clear of the marks: 0)
// beats B; with one label throughout, or no draw asked, B.
TEST(PatchPass, WhereClassesMeetThePlacesDrawnAroundTheSourceCompete) {
  const ExemplarLevel e = exemplar();
  std::vector<uint8_t> meeting(25, 0);
  meeting[0] = 1;
  const int32_t drawn = passed(e, window_state(), {}, 0, 0, meeting, kMaxPatchSearch);
  EXPECT_NE(drawn, at(kA));
  EXPECT_NE(drawn, at(kB));
  EXPECT_NE(drawn, at(kC));
  const int x = drawn % kSide, y = drawn / kSide;
  EXPECT_LE(std::abs(x - kC.first), kPatchSearchRadius);
  EXPECT_LE(std::abs(y - kC.second), kPatchSearchRadius);
  for (int dy = -2; dy <= 2; ++dy)
    for (int dx = -2; dx <= 2; ++dx)
      EXPECT_EQ(e.rgb[3 * size_t(e.index(x + dx, y + dy))], 0.5f) << dx << ", " << dy;
  EXPECT_EQ(passed(e, window_state(), {}, 0, 0, std::vector<uint8_t>(25, 0), kMaxPatchSearch),
            at(kB));
  EXPECT_EQ(passed(e, window_state(), {}, 0, 0, meeting, 0), at(kB));
}

// The exemplar's class edges: with its rows 0-1 of label 1 and 38-39 of label 2, its places of
// label 0 beside label 1 are rows 2-9, beside label 2 rows 30-37 (class_edges.h). Where the
// target's classes meet, a place drawn from the run of p's label and the other label most present
// in its window (patch clear of the marks: 0) beats B; with one label throughout, or no draw
// asked, B.
TEST(PatchPass, WhereClassesMeetThePlacesDrawnFromTheExemplarsClassEdgesCompete) {
  ExemplarLevel e = exemplar();
  for (int x = 0; x < kSide; ++x)
    for (const int y : {0, 1, 38, 39}) e.labels[size_t(e.index(x, y))] = y < 2 ? 1 : 2;
  for (int32_t i = 0; i < kSide * kSide; ++i) e.allowed.push_back(i);
  e.class_edges = class_edge_places(e);
  const auto drawn_row = [&](const std::vector<uint8_t>& labels) {
    const int32_t drawn = passed(e, window_state(), {}, 0, 0, labels, 0, kMaxPatchEdges);
    EXPECT_NE(drawn, at(kA));
    EXPECT_NE(drawn, at(kB));
    EXPECT_NE(drawn, at(kC));
    const int x = drawn % kSide, y = drawn / kSide;
    for (int dy = -2; dy <= 2; ++dy)
      for (int dx = -2; dx <= 2; ++dx)
        EXPECT_EQ(e.rgb[3 * size_t(e.index(x + dx, y + dy))], 0.5f) << dx << ", " << dy;
    return y;
  };
  std::vector<uint8_t> meeting(25, 0);
  meeting[0] = 1;
  const int beside_1 = drawn_row(meeting);
  EXPECT_GE(beside_1, 2);
  EXPECT_LE(beside_1, 9);
  meeting[1] = meeting[2] = 2;  // label 2 now the most present other
  const int beside_2 = drawn_row(meeting);
  EXPECT_GE(beside_2, 30);
  EXPECT_LE(beside_2, 37);
  EXPECT_EQ(passed(e, window_state(), {}, 0, 0, std::vector<uint8_t>(25, 0), 0, kMaxPatchEdges),
            at(kB));
  EXPECT_EQ(passed(e, window_state(), {}, 0, 0, meeting, 0, 0), at(kB));
}

// The altitude guide: with B's altitude 0.5 away from the target's and A's and C's on it, B's
// 0.12 + 1 x 24 / 9 x 0.25 = 0.787 loses to A's 0.75; with w_altitude 0.1 (0.187), or no target
// altitude, B wins.
TEST(PatchPass, TheAltitudeGuideIsWeighed) {
  ExemplarLevel e = exemplar();
  e.altitude.assign(e.labels.size(), 0.2f);
  e.altitude[size_t(at(kB))] = 0.7f;
  const std::vector<float> altitude(25, 0.2f);
  EXPECT_EQ(passed_with_altitude(e, window_state(), altitude, 1), at(kA));
  EXPECT_EQ(passed_with_altitude(e, window_state(), altitude, 0.1), at(kB));
  EXPECT_EQ(passed_with_altitude(e, window_state(), {}, 1), at(kB));
}

}  // namespace
}  // namespace maquette::synthesis
