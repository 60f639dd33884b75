#include "least_cost.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace maquette::synthesis {
namespace {

struct Candidate {
  bool fits;
  double floor, cost;
};

// The rule of least_cost.h stated plainly, every cost weighed.
int weighed_all(const std::vector<Candidate>& c) {
  int winner = -1;
  bool winner_fits = false;
  double least = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < c.size(); ++i) {
    if (winner_fits && !c[i].fits) continue;
    if (c[i].cost < least || (c[i].fits && !winner_fits))
      least = c[i].cost, winner = int(i), winner_fits = c[i].fits;
  }
  return winner;
}

// Candidates with costs on a coarse grid (ties), some NaN, and floors at, under or far under
// their costs, -infinity or NaN.
std::vector<Candidate> drawn(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> count(0, 30), step(0, 20), kind(0, 9);
  std::vector<Candidate> c(size_t(count(rng)));
  for (Candidate& x : c) {
    x.fits = kind(rng) < 5;
    x.cost = kind(rng) == 0 ? std::nan("") : 0.5 * step(rng);
    switch (kind(rng)) {
      case 0:
        x.floor = -std::numeric_limits<double>::infinity();
        break;
      case 1:
        x.floor = std::nan("");
        break;
      case 2:
        x.floor = x.cost;
        break;
      default:
        x.floor = std::isnan(x.cost) ? 0.0 : x.cost - 0.25 * step(rng);
    }
  }
  return c;
}

TEST(LeastCost, ChoosesWhatWeighingEveryCostChooses) {
  std::mt19937_64 rng(7);
  size_t dismissed = 0, offered = 0;
  for (int trial = 0; trial < 100000; ++trial) {
    const std::vector<Candidate> c = drawn(rng);
    std::vector<int> floors(c.size(), 0), costs(c.size(), 0);
    int last_floor = -1;
    const int chosen = least_cost(
        c.size(), [&](size_t i) { return c[i].fits; },
        [&](size_t i) {
          ++floors[i];
          last_floor = int(i);
          return c[i].floor;
        },
        [&](size_t i) {
          ++costs[i];
          EXPECT_EQ(last_floor, int(i)) << "cost(i) without floor(i) just before it";
          return c[i].cost;
        });
    ASSERT_EQ(chosen, weighed_all(c)) << "trial " << trial;
    for (size_t i = 0; i < c.size(); ++i) {
      ASSERT_LE(floors[i], 1);
      ASSERT_LE(costs[i], floors[i]);
      offered += floors[i];
      dismissed += size_t(floors[i] - costs[i]);
    }
  }
  // The floors do dismiss candidates (so the comparison above tested the dismissal).
  EXPECT_GT(dismissed, offered / 5);
}

TEST(LeastCost, AFittingCandidateWinsWhateverItsFloorAndCost) {
  const std::vector<Candidate> c = {{false, 0.0, 0.5}, {true, 1e9, 1e9}, {false, 0.0, 0.1}};
  const auto fits = [&](size_t i) { return c[i].fits; };
  const auto floor = [&](size_t i) { return c[i].floor; };
  const auto cost = [&](size_t i) { return c[i].cost; };
  EXPECT_EQ(least_cost(c.size(), fits, floor, cost), 1);
  EXPECT_EQ(least_cost(size_t(0), fits, floor, cost), -1);
}

}  // namespace
}  // namespace maquette::synthesis
