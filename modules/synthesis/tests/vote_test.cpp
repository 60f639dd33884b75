// The finest level's vote (vote.h) on hand-built cases whose answers are worked out here: a
// 3 x 3 window's proposals chosen so that the nearest-to-the-mean rule, the majority, the pixel's
// own source and a proposal that should be ignored each give a different winner; the depth-break
// rule kept and lifted by the depth of one neighbour.
#include "../vote.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <utility>

namespace maquette::synthesis {
namespace {

constexpr int kSide = 8;

// A grey exemplar of kSide x kSide pixels, label 0, nothing excluded; pixels set by `greys`.
ExemplarLevel exemplar(const std::map<std::pair<int, int>, float>& greys) {
  ExemplarLevel e;
  e.width = e.height = kSide;
  e.rgb.assign(3 * kSide * kSide, 0.5f);
  e.labels.assign(kSide * kSide, 0);
  e.excluded.assign(kSide * kSide, 0);
  for (const auto& [xy, grey] : greys)
    for (size_t k = 0; k < 3; ++k) e.rgb[3 * size_t(e.index(xy.first, xy.second)) + k] = grey;
  return e;
}

// The proposals below, in row-major order of d over the window of radius 1: A (grey 0) four
// times, B (0.6) three times, C (1) once and X (0.3) once. Counted without X, their mean is
// 2.8 / 8 = 0.35: B is nearest (0.25 away; A 0.35, C 0.65), though A is the majority and the
// pixel's own source. Counted with X, the mean is 3.1 / 9 = 0.344 and X (0.044 away) wins.
constexpr std::pair<int, int> kA{2, 2}, kB{5, 5}, kC{1, 6}, kX{6, 1};
const std::map<std::pair<int, int>, float> kGreys{{kA, 0.0f}, {kB, 0.6f}, {kC, 1.0f}, {kX, 0.3f}};
constexpr std::pair<int, int> kProposals[9] = {kA, kB, kA, kC, kA, kB, kX, kA, kB};

constexpr PixelRect kPixel{0, 0, 1, 1};
constexpr PixelRect kWindow{-1, -1, 3, 3};

// The state whose window proposes `proposals`: S(d) = P(d) + d.
std::vector<int32_t> state_of(const std::pair<int, int> (&proposals)[9]) {
  std::vector<int32_t> state(9);
  for (int i = 0; i < 9; ++i) {
    const int dx = i % 3 - 1, dy = i / 3 - 1;
    state[size_t(i)] = (proposals[i].second + dy) * kSide + proposals[i].first + dx;
  }
  return state;
}

int32_t voted(const ExemplarLevel& e, const std::vector<int32_t>& state, uint8_t label,
              const std::vector<float>& depth = {}, int radius = 1) {
  const std::vector<uint8_t> labels(9, label);
  return vote(e, {kWindow, state, kWindow, labels, depth, 1.05}, radius, kPixel).at(0);
}

int32_t at(std::pair<int, int> xy) { return xy.second * kSide + xy.first; }

TEST(Vote, TakesTheProposalNearestTheMeanNotTheMajorityAndIgnoresAnExcludedOne) {
  ExemplarLevel e = exemplar(kGreys);
  const auto state = state_of(kProposals);
  e.excluded[size_t(at(kX))] = 1;
  EXPECT_EQ(voted(e, state, 0), at(kB));
  e.excluded[size_t(at(kX))] = 0;
  EXPECT_EQ(voted(e, state, 0), at(kX));  // counted, X is nearest the mean
}

// The histogram balance: with B's colour over-shown 4 times and A's under-shown (excess 0.25),
// B's squared distance to the mean 3 x 0.25^2 = 0.1875 weighs 0.75 and A's 3 x 0.35^2 = 0.3675
// weighs 0.092: A wins; at balance 0, or with no excess measured, B as above.
TEST(Vote, TheBalanceWeighsEachProposalByItsColoursExcess) {
  ExemplarLevel e = exemplar(kGreys);
  e.excluded[size_t(at(kX))] = 1;
  const auto state = state_of(kProposals);
  const std::vector<uint8_t> labels(9, 0);
  const auto balanced = [&](double balance) {
    return vote(e, {kWindow, state, kWindow, labels, {}, 1.05, balance}, 1, kPixel).at(0);
  };
  EXPECT_EQ(balanced(1), at(kB));  // no excess measured
  e.colour_excess.assign(kSide * kSide, 1.0f);
  e.colour_excess[size_t(at(kA))] = 0.25f;
  e.colour_excess[size_t(at(kB))] = 4.0f;
  EXPECT_EQ(balanced(0), at(kB));
  EXPECT_EQ(balanced(1), at(kA));
}

TEST(Vote, IgnoresAProposalOfAnotherLabelUnlessThePixelsIsUnknown) {
  ExemplarLevel e = exemplar(kGreys);
  e.labels[size_t(at(kX))] = 1;
  const auto state = state_of(kProposals);
  EXPECT_EQ(voted(e, state, 0), at(kB));
  EXPECT_EQ(voted(e, state, kUnknownLabel), at(kX));
}

TEST(Vote, IgnoresAProposalOutsideTheExemplar) {
  const ExemplarLevel e = exemplar(kGreys);
  auto state = state_of(kProposals);
  state[6] = kSide - 1;  // d = (-1, 1) at exemplar (7, 0) proposes (8, -1)
  EXPECT_EQ(voted(e, state, 0), at(kB));
}

TEST(Vote, TiesGoToTheFirstProposalInRowMajorOrder) {
  // C (grey 1) at d = (-1, -1) and A (grey 0) at d = (0, 0), both 0.5 from their mean; every
  // other patch proposes the excluded E.
  constexpr std::pair<int, int> kE{3, 3};
  ExemplarLevel e = exemplar(kGreys);
  e.excluded[size_t(at(kE))] = 1;
  EXPECT_EQ(voted(e, state_of({kC, kE, kE, kE, kA, kE, kE, kE, kE}), 0), at(kC));
  EXPECT_EQ(voted(e, state_of({kA, kE, kE, kE, kC, kE, kE, kE, kE}), 0), at(kA));
}

TEST(Vote, RadiusZeroKeepsTheSource) {
  const ExemplarLevel e = exemplar(kGreys);
  EXPECT_EQ(voted(e, state_of(kProposals), 0, {}, 0), at(kA));
}

TEST(Vote, NoVoteBesideASilhouette) {
  ExemplarLevel e = exemplar(kGreys);
  e.excluded[size_t(at(kX))] = 1;
  const auto state = state_of(kProposals);
  const float sky = std::numeric_limits<float>::infinity();
  std::vector<float> depth(9, 100.0f);
  EXPECT_EQ(voted(e, state, 0, depth), at(kB));  // one depth: the vote as without
  depth[8] = 104.0f;                             // 1.04 times farther: no break
  EXPECT_EQ(voted(e, state, 0, depth), at(kB));
  depth[8] = 106.0f;  // 1.06 > depth_break 1.05: the pixel keeps its own source
  EXPECT_EQ(voted(e, state, 0, depth), at(kA));
  depth[8] = 100.0f;
  depth[2] = sky;  // the sky beside it
  EXPECT_EQ(voted(e, state, 0, depth), at(kA));
  depth[2] = std::nanf("");  // unknown depth breaks nothing
  EXPECT_EQ(voted(e, state, 0, depth), at(kB));
}

TEST(AcrossDepthBreak, SkyNearFarAndUnknown) {
  const float sky = std::numeric_limits<float>::infinity(), unknown = std::nanf("");
  EXPECT_TRUE(across_depth_break(100, 106, 1.05));
  EXPECT_TRUE(across_depth_break(106, 100, 1.05));
  EXPECT_FALSE(across_depth_break(100, 104, 1.05));
  EXPECT_TRUE(across_depth_break(100, sky, 1.05));
  EXPECT_FALSE(across_depth_break(sky, sky, 1.05));
  EXPECT_FALSE(across_depth_break(unknown, 1000, 1.05));
}

}  // namespace
}  // namespace maquette::synthesis
