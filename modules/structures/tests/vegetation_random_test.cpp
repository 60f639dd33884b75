// random_placement (vegetation_random.h), the paper's area-weighted uniform placement, against
// the analytic Poisson process: the count, every plant in the polygon and none in its hole, the
// share of each part by area, and the paper's flaw measured beside poisson_disk's blue noise.
#include "../vegetation_random.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <utility>
#include <vector>

#include "../poisson_disk.h"

namespace maquette::structures {
namespace {

// The fraction of points with another closer than d (buckets of side d, 3 x 3 around each).
double fraction_closer(const std::vector<PlanePoint>& points, double d) {
  std::map<std::pair<int64_t, int64_t>, std::vector<PlanePoint>> buckets;
  const auto key = [d](PlanePoint p) {
    return std::pair(int64_t(std::floor(p.x / d)), int64_t(std::floor(p.y / d)));
  };
  for (const PlanePoint& p : points) buckets[key(p)].push_back(p);
  size_t closer = 0;
  for (const PlanePoint& p : points) {
    const auto [i, j] = key(p);
    bool found = false;
    for (int64_t b = j - 1; b <= j + 1 && !found; ++b)
      for (int64_t a = i - 1; a <= i + 1 && !found; ++a) {
        const auto it = buckets.find({a, b});
        if (it == buckets.end()) continue;
        for (const PlanePoint& q : it->second)
          if ((q.x != p.x || q.y != p.y) && std::hypot(q.x - p.x, q.y - p.y) < d) found = true;
      }
    closer += found;
  }
  return double(closer) / double(points.size());
}

// An L of two 60 x 30 arms (area 2700) with a 10 x 10 hole in the corner square.
const std::vector<PlaneRing> kLRings = {
    {{0, 0}, {60, 0}, {60, 30}, {30, 30}, {30, 60}, {0, 60}, {0, 0}},
    {{10, 10}, {20, 10}, {20, 20}, {10, 20}, {10, 10}}};

const Footprint kL = make_footprint(kLRings);

TEST(RandomPlacement, AreaOverSpacingSquaredPlantsInThePolygon) {
  const double spacing = 0.5;  // 2600 / 0.25 = 10,400 plants
  const auto points = random_placement(kL, spacing, 5);
  EXPECT_EQ(points.size(), 10400u);
  const PolygonSet region({{{{0, 0}, {60, 0}, {60, 30}, {30, 30}, {30, 60}, {0, 60}, {0, 0}},
                            {{10, 10}, {20, 10}, {20, 20}, {10, 20}, {10, 10}}}});
  size_t outside = 0, east_arm = 0;
  for (const PlanePoint& p : points) {
    outside += !region.contains({p.x, p.y});
    east_arm += p.x > 30;
  }
  EXPECT_EQ(outside, 0u);
  // The east arm (30 x 30 = 900 of 2600): binomial, 3 standard deviations.
  const double n = double(points.size()), share = 900.0 / 2600.0;
  EXPECT_NEAR(double(east_arm), n * share, 3 * std::sqrt(n * share * (1 - share)));
}

TEST(RandomPlacement, DeterministicBySeed) {
  const auto a = random_placement(kL, 2, 9), b = random_placement(kL, 2, 9);
  const auto c = random_placement(kL, 2, 10);
  ASSERT_EQ(a.size(), b.size());
  for (size_t k = 0; k < a.size(); ++k) EXPECT_TRUE(a[k].x == b[k].x && a[k].y == b[k].y);
  EXPECT_NE(a.front().x, c.front().x);
}

TEST(RandomPlacement, ThePapersFlawAgainstBlueNoise) {
  // A 200 x 200 spacings square: the border strip where neighbours are missing is 1 % of it.
  const double spacing = 2, side = 400;
  const Footprint square = make_footprint({{{0, 0}, {side, 0}, {side, side}, {0, side}}});
  const double random = fraction_closer(random_placement(square, spacing, 1), spacing / 2);
  // A Poisson process of density 1 / spacing^2: P(a neighbour within spacing / 2).
  EXPECT_NEAR(random, 1 - std::exp(-std::numbers::pi / 4), 0.01);
  const PolygonSet region({{{{0, 0}, {side, 0}, {side, side}, {0, side}, {0, 0}}}});
  const auto blue = poisson_disk(region, poisson_min_distance(spacing), 1, {0, 0, side, side});
  EXPECT_EQ(fraction_closer(blue, spacing / 2), 0.0);
  std::printf(
      "plants with a neighbour closer than half the spacing: random %.1f %%, "
      "poisson 0 %% of %zu\n",
      100 * random, blue.size());
}

}  // namespace
}  // namespace maquette::structures
