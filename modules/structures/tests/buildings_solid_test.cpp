// Extruded footprints against CGAL (cgal_oracle.h) and analytic volumes: closed, consistently
// outward, no self-intersection, volume = area x height; and the module's own checks
// (solid_problem) failing on broken solids.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "../building_solid.h"
#include "../roof_triangulation.h"
#include "cgal_oracle.h"

namespace maquette::structures {
namespace {

PlaneRing rectangle(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

void expect_valid(const Solid& s, double volume) {
  expect_valid_solid(s.positions, s.indices, volume);
  EXPECT_EQ(solid_problem(s, volume), "");
}

TEST(BuildingSolid, BoxHasTheVolumeOfItsSides) {
  const Solid s = extrude(make_footprint({rectangle(0, 0, 10, 20)}), 7);
  expect_valid(s, 10 * 20 * 7);
  EXPECT_EQ(s.indices.size() / 3, 2 * 2 + 4 * 2u);  // two triangles each cap, two each wall
}

TEST(BuildingSolid, CourtyardKeepsItsInnerWalls) {
  // A 30 m square with a 10 m courtyard, the hole given counter-clockwise (turned by
  // make_footprint).
  const Footprint fp = make_footprint({rectangle(0, 0, 30, 30), rectangle(10, 10, 20, 20)});
  EXPECT_DOUBLE_EQ(fp.area, 800);
  const Solid s = extrude(fp, 12.5);
  expect_valid(s, 800 * 12.5);
  // 8 walls of two triangles; the roof (8 points, one hole) has 8 triangles, the floor too.
  EXPECT_EQ(s.indices.size() / 3, 8 + 8 + 16u);
  // The courtyard is open: no roof triangle has its centroid in it.
  for (size_t t = 3 * s.faces[1].first; t < 3 * (s.faces[1].first + s.faces[1].count); t += 3) {
    double cx = 0, cy = 0;
    for (size_t k = 0; k < 3; ++k) {
      cx += s.positions[3 * s.indices[t + k]] / 3;
      cy += s.positions[3 * s.indices[t + k] + 1] / 3;
    }
    EXPECT_FALSE(cx > 10 && cx < 20 && cy > 10 && cy < 20) << cx << ", " << cy;
  }
}

TEST(BuildingSolid, ConcaveFootprintWithTwoCourtyardsAndCollinearPoints) {
  // A U shape with points in the middle of straight edges, and two holes in its base.
  const PlaneRing u = {{0, 0},   {20, 0},  {40, 0},  {40, 30}, {30, 30},
                       {30, 10}, {10, 10}, {10, 30}, {0, 30},  {0, 15}};
  const Footprint fp = make_footprint({u, rectangle(2, 2, 8, 8), rectangle(32, 2, 38, 8)});
  const double area = 40 * 30 - 20 * 20 - 2 * 36;
  EXPECT_NEAR(fp.area, area, 1e-12);
  EXPECT_NEAR(fp.area, cgal_area({u, rectangle(2, 2, 8, 8), rectangle(32, 2, 38, 8)}), 1e-12);
  expect_valid(extrude(fp, 31.7), area * 31.7);
}

TEST(BuildingSolid, RoofTrianglesCoverTheFootprint) {
  const Footprint fp = make_footprint({{{0, 0}, {50, 3}, {47, 41}, {25, 20}, {-4, 38}}});
  const std::vector<uint32_t> t = triangulate_footprint(fp);
  std::vector<double> xy;
  for (const PlanePoint2& p : fp.rings[0]) xy.insert(xy.end(), {p[0], p[1]});
  double sum = 0;
  for (size_t k = 0; k < t.size(); k += 3) {
    const double twice =
        (xy[2 * t[k + 1]] - xy[2 * t[k]]) * (xy[2 * t[k + 2] + 1] - xy[2 * t[k] + 1]) -
        (xy[2 * t[k + 1] + 1] - xy[2 * t[k] + 1]) * (xy[2 * t[k + 2]] - xy[2 * t[k]]);
    EXPECT_GT(twice, 0);  // counter-clockwise
    sum += twice / 2;
  }
  EXPECT_NEAR(sum, cgal_area({fp.rings[0]}), 1e-9);
  EXPECT_EQ(t.size(), 3 * 3u);  // n - 2 triangles
}

TEST(BuildingSolid, ThinWallOfATallBuildingIsValid) {
  // A 1 cm wide, 20 m long slab, 150 m tall: its end walls are triangles of 1 cm by 150 m (area
  // over longest edge squared 3.3e-5), far from slivers.
  const Footprint fp = make_footprint({rectangle(0, 0, 20, 0.01)});
  expect_valid(extrude(fp, 150), fp.area * 150);
}

TEST(BuildingSolid, SliverRoofIsRefused) {
  // A triangle 1 km long and 30 micrometres high (0.015 m2, above kMinRingAreaM2): its roof and
  // floor are one triangle each, of area 1.5e-8 times its longest edge squared.
  const Footprint fp = make_footprint({{{0, 0}, {1000, 0}, {500, 3e-5}}});
  const Solid s = extrude(fp, 10);
  ASSERT_EQ(s.faces[0].count, 1u);
  const std::string problem = solid_problem(s, fp.area * 10);
  EXPECT_NE(problem.find("triangle 0 is a sliver: area 0.015 m2 for a longest edge of 1000 m"),
            std::string::npos)
      << problem;
  // The same footprint scaled across to 3 cm high (1.5e-5: well shaped enough) is valid.
  const Footprint wider = make_footprint({{{0, 0}, {1000, 0}, {500, 0.03}}});
  EXPECT_EQ(solid_problem(extrude(wider, 10), wider.area * 10), "");
}

TEST(BuildingSolid, OwnChecksFindBrokenSolids) {
  const Solid good = extrude(make_footprint({rectangle(0, 0, 10, 10)}), 5);
  ASSERT_EQ(solid_problem(good, 500), "");
  Solid flipped = good;
  std::swap(flipped.indices[0], flipped.indices[1]);
  EXPECT_NE(solid_problem(flipped, 500).find("direction"), std::string::npos);
  EXPECT_FALSE(cgal_verdict(flipped.positions, flipped.indices).polygon_mesh);
  Solid open = good;
  open.indices.resize(open.indices.size() - 3);
  EXPECT_NE(solid_problem(open, 500).find("not closed"), std::string::npos);
  EXPECT_FALSE(cgal_verdict(open.positions, open.indices).closed);
  Solid inward = good;
  for (size_t t = 0; t < inward.indices.size(); t += 3)
    std::swap(inward.indices[t], inward.indices[t + 1]);
  EXPECT_NE(solid_problem(inward, 500).find("inwards"), std::string::npos);
  EXPECT_FALSE(cgal_verdict(inward.positions, inward.indices).outward);
  Solid bent = good;
  bent.positions[3 * 4 + 2] += 0.02;  // a roof corner 2 cm up
  EXPECT_NE(solid_problem(bent, 500).find("not planar"), std::string::npos);
  EXPECT_NE(solid_problem(good, 500 * (1 + 2e-9)).find("volume"), std::string::npos);
}

}  // namespace
}  // namespace maquette::structures
