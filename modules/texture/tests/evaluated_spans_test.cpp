// The spans of a lattice row known evaluated (evaluated_spans.h): requests evaluate exactly the
// nodes they lack, each node at most once, also when the spans overflow and two are joined.
#include "../evaluated_spans.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace maquette::texture {
namespace {

TEST(EvaluatedSpans, EvaluatesWhatIsMissingOnce) {
  EvaluatedSpans spans;
  std::vector<std::pair<int, int>> calls;
  const auto record = [&](int a, int b) { calls.emplace_back(a, b); };
  spans.fill(10, 20, record);
  spans.fill(12, 18, record);  // inside: nothing
  spans.fill(30, 40, record);
  spans.fill(5, 35, record);  // the gaps on either side and between
  spans.fill(0, 45, record);
  const std::vector<std::pair<int, int>> expected{{10, 20}, {30, 40}, {5, 9},
                                                  {21, 29}, {0, 4},   {41, 45}};
  EXPECT_EQ(calls, expected);
}

// Random requests over a row of 200 nodes, with more disjoint pieces than spans are kept: every
// requested node is evaluated before the request returns, and none twice.
TEST(EvaluatedSpans, EveryNodeOnceUnderOverflow) {
  std::mt19937 random(7);
  for (int round = 0; round < 200; ++round) {
    EvaluatedSpans spans;
    std::vector<int> times(200, 0);
    for (int request = 0; request < 40; ++request) {
      const int first = int(random() % 200), length = int(random() % 12);
      const int last = std::min(199, first + length);
      spans.fill(first, last, [&](int a, int b) {
        ASSERT_LE(a, b);
        for (int i = a; i <= b; ++i) ++times[size_t(i)];
      });
      for (int i = first; i <= last; ++i) ASSERT_EQ(times[size_t(i)], 1) << round << " " << i;
    }
    for (const int t : times) ASSERT_LE(t, 1) << round;
  }
}

}  // namespace
}  // namespace maquette::texture
