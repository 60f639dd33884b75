// The bridge deck's solid (bridge_deck.h) against CGAL (cgal_oracle.h) and analytic values: a
// curved deck whose four ends stand at different heights (a top of many planes) is closed,
// outward, free of self-intersection, of volume outline area (CGAL's) x thickness; its top passes
// through the edge points and its floor lies the thickness below; the profile is linear in arc
// length; crossing edges and a deck of no area are refused.
#include "../bridge_deck.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "cgal_oracle.h"

namespace maquette::structures {
namespace {

TEST(BridgeDeck, ProfileIsLinearInArcLength) {
  // Segments of 3, 4 (a turn) and 5 m: 12 m from 10 to 22 m.
  const std::vector<double> h = edge_profile({{0, 0}, {3, 0}, {3, 4}, {6, 8}}, 10, 22);
  ASSERT_EQ(h.size(), 4u);
  EXPECT_DOUBLE_EQ(h[0], 10);
  EXPECT_DOUBLE_EQ(h[1], 13);
  EXPECT_DOUBLE_EQ(h[2], 17);
  EXPECT_DOUBLE_EQ(h[3], 22);
}

// An arc of `n` + 1 points at radius `r` around (0, -100), from -0.3 to 0.3 rad, its heights
// linear in arc length from `start` to `end`.
std::vector<DeckPoint> arc(double r, int n, double start, double end) {
  std::vector<PlanePoint2> plane;
  for (int k = 0; k <= n; ++k) {
    const double t = -0.3 + 0.6 * k / n;
    plane.push_back({r * std::sin(t), r * std::cos(t) - 100});
  }
  const std::vector<double> h = edge_profile(plane, start, end);
  std::vector<DeckPoint> out;
  for (int k = 0; k <= n; ++k) out.push_back({plane[k][0], plane[k][1], h[k]});
  return out;
}

TEST(BridgeDeck, CurvedDeckWithFourEndHeightsIsAValidSolid) {
  const std::vector<DeckPoint> first = arc(100, 12, 30, 45), second = arc(108, 9, 33, 41);
  const double thickness = 1.5;
  const Solid s = deck_solid(first, second, thickness);
  // The outline: the first edge, the second reversed.
  std::vector<std::array<double, 2>> outline;
  for (const DeckPoint& p : first) outline.push_back({p[0], p[1]});
  for (auto p = second.rbegin(); p != second.rend(); ++p) outline.push_back({(*p)[0], (*p)[1]});
  expect_valid_solid(s.positions, s.indices, cgal_area({outline}) * thickness);
  // Floor then top, point for point; the first is the first edge's first point.
  const size_t n = s.positions.size() / 6;
  ASSERT_EQ(n, first.size() + second.size());
  EXPECT_EQ(s.positions[0], first[0][0]);
  EXPECT_EQ(s.positions[1], first[0][1]);
  for (size_t i = 0; i < n; ++i) {
    const double x = s.positions[3 * i], y = s.positions[3 * i + 1];
    const double floor = s.positions[3 * i + 2], top = s.positions[3 * (n + i) + 2];
    EXPECT_EQ(s.positions[3 * (n + i)], x);
    EXPECT_NEAR(top - floor, thickness, 1e-12);
    bool on_an_edge = false;
    for (const auto* edge : {&first, &second})
      for (const DeckPoint& p : *edge)
        if (p[0] == x && p[1] == y) {
          on_an_edge = true;
          EXPECT_EQ(top, p[2]);
        }
    EXPECT_TRUE(on_an_edge) << i;
  }
}

TEST(BridgeDeck, SecondEdgeDrawnInEitherSenseOfTheOutlineWorks) {
  // The outline is clockwise when the second edge lies to the first's right: make_footprint
  // turns it, and the solid is still outward.
  const std::vector<DeckPoint> south = {{0, 0, 10}, {100, 0, 20}},
                               north = {{0, 10, 10}, {100, 10, 20}};
  for (const auto& [a, b] : {std::pair(south, north), std::pair(north, south)}) {
    const Solid s = deck_solid(a, b, 2);
    expect_valid_solid(s.positions, s.indices, 100 * 10 * 2);
  }
}

TEST(BridgeDeck, CrossingEdgesAndNoAreaAreRefused) {
  const std::vector<DeckPoint> first = {{0, 0, 10}, {100, 0, 20}};
  try {
    deck_solid(first, {{0, 10, 10}, {50, -10, 15}, {100, 10, 20}}, 1);
    ADD_FAILURE() << "crossing edges accepted";
  } catch (const InvalidFootprint& e) {
    EXPECT_NE(std::string(e.what()).find("the deck between the edges is not a simple polygon"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(deck_solid(first, first, 1), InvalidFootprint);
}

}  // namespace
}  // namespace maquette::structures
