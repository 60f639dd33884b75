// A stroke's field of influence around a bend: the outer side of the turn, where a point projects
// onto neither segment, belongs to the band as far as the cross section reaches (the section at
// the vertex runs along the bisector), and no further.
#include "../stroke_band.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace maquette::deform {
namespace {

// A curve turning left by 30 degrees at (100, 0); travel east, so its right is south.
StrokeBand bend(double offset_min, double offset_max) {
  const double turn = std::numbers::pi / 6;
  return {{{0, 0}, {100, 0}, {100 + 100 * std::cos(turn), 100 * std::sin(turn)}},
          offset_min,
          offset_max,
          0};
}

// The point `distance` from the vertex along the outer wedge's middle (between the two segments'
// right normals, -90 and -60 degrees).
EastNorth2 outer(double distance) {
  const double angle = -75 * std::numbers::pi / 180;
  return {100 + distance * std::cos(angle), distance * std::sin(angle)};
}

TEST(StrokeBand, OuterSideOfABendIsInTheBandUpToTheSectionsReach) {
  const StrokeBand band = bend(-20, 20);
  EXPECT_TRUE(band.contains(outer(15)));
  EXPECT_TRUE(band.contains(outer(19.9)));
  EXPECT_FALSE(band.contains(outer(20.1)));
  // The inner side, reached by both segments' projections.
  EXPECT_TRUE(band.contains({100 - 15 * std::cos(-75 * std::numbers::pi / 180),
                             -15 * std::sin(-75 * std::numbers::pi / 180)}));
}

TEST(StrokeBand, OneSidedBandAtABendKeepsItsInnerOffset) {
  const StrokeBand right = bend(5, 20);
  EXPECT_FALSE(right.contains(outer(3)));
  EXPECT_TRUE(right.contains(outer(10)));
  EXPECT_FALSE(right.contains({100, 0}));
  EXPECT_FALSE(right.contains({100, -21}));
  const StrokeBand left = bend(-20, -5);
  EXPECT_FALSE(left.contains(outer(10)));
}

}  // namespace
}  // namespace maquette::deform
