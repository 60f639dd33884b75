// poisson_disk (poisson_disk.h): every pair of points at least the minimum distance apart (all
// pairs checked), every point in the region and none in its hole, the density of one point per
// spacing^2 on a large region and on small ones (no denser band along the edge), and the same
// points whatever windows (tilings) ask for them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <tuple>
#include <vector>

#include "../poisson_disk.h"

namespace maquette::structures {
namespace {

// A square of side `side` at the origin with a square hole of side side / 3 in its middle.
PolygonSet square_with_hole(double side) {
  const double a = side / 3, b = 2 * side / 3;
  return PolygonSet({{{{0, 0}, {side, 0}, {side, side}, {0, side}, {0, 0}},
                      {{a, a}, {b, a}, {b, b}, {a, b}, {a, a}}}});
}

std::vector<PlanePoint> sorted(std::vector<PlanePoint> v) {
  std::sort(v.begin(), v.end(),
            [](PlanePoint a, PlanePoint b) { return std::tie(a.x, a.y) < std::tie(b.x, b.y); });
  return v;
}

bool same(const std::vector<PlanePoint>& a, const std::vector<PlanePoint>& b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](auto p, auto q) {
           return p.x == q.x && p.y == q.y;
         });
}

TEST(PoissonDisk, EveryPairIsAtLeastTheMinimumDistanceApart) {
  const double r = 1.7, side = 80;
  const PolygonSet region = square_with_hole(side);
  const auto points = poisson_disk(region, r, 7, {-5, -5, side + 5, side + 5});
  ASSERT_GT(points.size(), 1000u);
  double closest = 1e300;
  for (size_t a = 0; a < points.size(); ++a)
    for (size_t b = a + 1; b < points.size(); ++b)
      closest = std::min(closest, std::hypot(points[a].x - points[b].x, points[a].y - points[b].y));
  EXPECT_GE(closest, r);
  EXPECT_LT(closest, 1.01 * r);  // the sample is packed: some pairs are at about r
  for (const PlanePoint& p : points) {
    EXPECT_TRUE(p.x > 0 && p.x < side && p.y > 0 && p.y < side) << p.x << " " << p.y;
    EXPECT_FALSE(p.x > side / 3 && p.x < 2 * side / 3 && p.y > side / 3 && p.y < 2 * side / 3)
        << "in the hole: " << p.x << " " << p.y;
  }
}

TEST(PoissonDisk, OnePointPerSpacingSquared) {
  const double spacing = 3, side = 1200;  // 160,000 plants
  const PolygonSet region({{{{0, 0}, {side, 0}, {side, side}, {0, side}, {0, 0}}}});
  const auto points = poisson_disk(region, poisson_min_distance(spacing), 11, {0, 0, side, side});
  const double expected = side * side / (spacing * spacing);
  EXPECT_NEAR(double(points.size()) / expected, 1.0, 0.01) << points.size() << " points";
}

// Small regions (a garden of ~35 plants, where most plants are near the edge) get one point per
// spacing^2 too, on average over 200 of them at different places of the plane: points packed
// more densely along the edge would give ~20 % more.
TEST(PoissonDisk, SmallRegionsOnePointPerSpacingSquared) {
  const double spacing = 9, radius = 30;
  size_t count = 0;
  double area = 0;
  for (int k = 0; k < 200; ++k) {
    const double cx = 1000.0 * k + 0.37 * k * k, cy = 500.0 * (k % 7);
    std::vector<LonLat> ring;
    for (int t = 0; t <= 64; ++t) {
      const double a = 2 * std::numbers::pi * (t % 64) / 64;
      ring.push_back({cx + radius * std::cos(a), cy + radius * std::sin(a)});
    }
    area += 32 * std::sin(2 * std::numbers::pi / 64) * radius * radius;
    count += poisson_disk(PolygonSet({{ring}}), poisson_min_distance(spacing), 5,
                          {cx - radius, cy - radius, cx + radius, cy + radius})
                 .size();
  }
  EXPECT_NEAR(double(count) / (area / (spacing * spacing)), 1.0, 0.04) << count << " points";
  std::printf("%zu points, %.3f of one per spacing^2\n", count,
              double(count) / (area / (spacing * spacing)));
}

TEST(PoissonDisk, AnyTilingGivesTheSamePoints) {
  const double r = 2.3, side = 150;
  const PolygonSet region = square_with_hole(side);
  const auto whole = sorted(poisson_disk(region, r, 3, {-1, -1, side + 1, side + 1}));
  ASSERT_GT(whole.size(), 1000u);
  // Two tilings with edges at unrelated places (one tile narrower than the dependency halo).
  for (const std::vector<double>& edges : {std::vector<double>{-1, 13.7, 50, 50.3, 99.1, side + 1},
                                           std::vector<double>{-1, 37.77, 81.2, 140, side + 1}}) {
    std::vector<PlanePoint> tiled;
    for (size_t a = 0; a + 1 < edges.size(); ++a)
      for (size_t b = 0; b + 1 < edges.size(); ++b) {
        const auto tile =
            poisson_disk(region, r, 3, {edges[a], edges[b], edges[a + 1], edges[b + 1]});
        tiled.insert(tiled.end(), tile.begin(), tile.end());
      }
    EXPECT_TRUE(same(sorted(tiled), whole)) << tiled.size() << " tiled, " << whole.size();
  }
}

TEST(PoissonDisk, TheSeedChangesThePoints) {
  const PolygonSet region = square_with_hole(50);
  const auto a = poisson_disk(region, 2, 1, {0, 0, 50, 50});
  const auto b = poisson_disk(region, 2, 2, {0, 0, 50, 50});
  EXPECT_TRUE(same(a, poisson_disk(region, 2, 1, {0, 0, 50, 50})));
  EXPECT_FALSE(same(sorted(a), sorted(b)));
}

}  // namespace
}  // namespace maquette::structures
