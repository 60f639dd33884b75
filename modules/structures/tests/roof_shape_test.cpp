// Pitched roofs (roof_planes.h, roof_surface.h, building_solid.h) against closed forms and CGAL:
// a gabled, hipped, pyramidal and skillion roof on a rectangle, turned, give solids CGAL finds
// closed, outward, free of self-intersection, of the analytic volume to 1e-9; every Soho footprint
// and a concave one with courtyards, under each shape, gives a valid solid whose roof follows the
// lowest plane everywhere; the tags give the heights and frames the OSM wiki describes.
#include <gtest/gtest.h>

#include <GeographicLib/LocalCartesian.hpp>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "../building_solid.h"
#include "../roof_planes.h"
#include "../roof_surface.h"
#include "cgal_oracle.h"
#include "soho_scene.h"

namespace maquette::structures {
namespace {

constexpr RoofShape kPitched[] = {RoofShape::Gabled, RoofShape::Hipped, RoofShape::Pyramidal,
                                  RoofShape::Skillion};

// A length x width rectangle centred on (cx, cy), its long side at `angle` (rad) from east.
PlaneRing rectangle(double length, double width, double angle, double cx, double cy) {
  PlaneRing ring;
  for (const auto& [u, v] : {std::pair(-1.0, -1.0), {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}}) {
    const double x = u * length / 2, y = v * width / 2;
    ring.push_back({cx + x * std::cos(angle) - y * std::sin(angle),
                    cy + x * std::sin(angle) + y * std::cos(angle)});
  }
  return ring;
}

// The roof's volume over a length x width rectangle, `rise` high (the ridge along the length).
double roof_volume(RoofShape shape, double length, double width, double rise) {
  switch (shape) {
    case RoofShape::Gabled:
      return length * width * rise / 2;  // a triangular prism
    case RoofShape::Hipped:
      return width * rise * (3 * length - width) / 6;  // prism + pyramid
    case RoofShape::Pyramidal:
      return length * width * rise / 3;
    case RoofShape::Skillion:
      return length * width * rise / 2;  // a wedge
    case RoofShape::Flat:
      break;
  }
  return 0;
}

Solid solid_of(const Footprint& fp, RoofShape shape, const PartHeights& h, RoofSurface* out) {
  BuildingTags tags;
  tags.roof = shape;
  *out = roof_surface(fp, roof_planes(roof_frame(fp, tags), shape, h));
  return extrude(*out);
}

TEST(RoofShape, RectangleRoofsHaveTheirClosedFormVolume) {
  const double length = 23, width = 11, wall = 6, rise = 4.5;
  for (const double angle : {0.0, 0.3, -1.2, std::numbers::pi / 2})
    for (const RoofShape shape : kPitched) {
      SCOPED_TRACE(std::string(roof_shape_name(shape)) + " at " + std::to_string(angle));
      const Footprint fp = make_footprint({rectangle(length, width, angle, 310, -75)});
      RoofSurface roof;
      const Solid s = solid_of(fp, shape, {wall, rise}, &roof);
      const double volume = length * width * wall + roof_volume(shape, length, width, rise);
      expect_valid_solid(s.positions, s.indices, volume);
      EXPECT_NEAR(roof.volume(), volume, 1e-9 * volume);
      EXPECT_EQ(solid_problem(s, volume), "");
      double top = 0, low = INFINITY;
      for (const double z : roof.heights) top = std::max(top, z), low = std::min(low, z);
      EXPECT_NEAR(top, wall + rise, 1e-9);
      EXPECT_NEAR(low, wall, 1e-9);
      // Faces: the floor, one per plane, a wall per outline edge: a gable wall in two halves
      // under the ridge's ends, the others whole (the hips and pyramid's creases end at corners).
      const size_t planes = shape == RoofShape::Skillion ? 1 : shape == RoofShape::Gabled ? 2 : 4;
      const size_t outline = shape == RoofShape::Gabled ? 6 : 4;
      EXPECT_EQ(s.faces.size(), 1 + planes + outline);
      ASSERT_EQ(roof.outline.size(), 1u);
      EXPECT_EQ(roof.outline[0].size(), outline);
    }
}

TEST(RoofShape, GableWallsRiseToTheRidge) {
  // 20 x 10 east-west: the ridge along y = 5 from x = 0 to 20, 3 m above 7 m walls.
  const Footprint fp = make_footprint({{{0, 0}, {20, 0}, {20, 10}, {0, 10}}});
  RoofSurface roof;
  const Solid s = solid_of(fp, RoofShape::Gabled, {7, 3}, &roof);
  int apexes = 0;
  for (const uint32_t k : roof.outline[0])
    if (roof.heights[k] > 9.999) {
      EXPECT_NEAR(roof.points[k][1], 5, 1e-12);
      EXPECT_TRUE(roof.points[k][0] == 0 || roof.points[k][0] == 20);
      ++apexes;
    }
  EXPECT_EQ(apexes, 2);
  expect_valid_solid(s.positions, s.indices, 20 * 10 * 7 + 20 * 10 * 3 / 2.0);
}

TEST(RoofShape, SquareHippedRoofIsAPyramid) {
  // Equal sides: the hipped roof's ridge has no length.
  const Footprint fp = make_footprint({rectangle(12, 12, 0.4, 0, 0)});
  RoofSurface roof;
  const Solid s = solid_of(fp, RoofShape::Hipped, {5, 6}, &roof);
  expect_valid_solid(s.positions, s.indices, 144 * 5 + 144 * 6 / 3.0);
}

// The lowest of the planes at p.
double lowest(const std::vector<RoofPlane>& planes, const PlanePoint2& p) {
  double z = INFINITY;
  for (const RoofPlane& plane : planes) z = std::min(z, plane.at(p));
  return z;
}

// The roof of `shape` over `fp` (9 m walls, a pitch of 0.5 rad) gives a valid solid (by the
// module's checks and CGAL's) whose roof is the lowest plane everywhere: at each roof triangle's
// centroid and the midpoints of its edges (a triangle across a crease would be above it there).
void expect_roof_follows_planes(const Footprint& fp, RoofShape shape) {
  BuildingTags tags;
  tags.roof = shape;
  const RoofFrame rf = roof_frame(fp, tags);
  const std::vector<RoofPlane> planes =
      roof_planes(rf, shape, {9, std::tan(0.5) * roof_run(rf, shape)});
  RoofSurface roof;
  try {
    roof = roof_surface(fp, planes);
  } catch (const InvalidFootprint& e) {
    ADD_FAILURE() << e.what();
    return;
  }
  const Solid s = extrude(roof);
  EXPECT_EQ(solid_problem(s, roof.volume()), "");
  expect_valid_solid(s.positions, s.indices, roof.volume());
  for (const std::vector<uint32_t>& face : roof.faces)
    for (size_t t = 0; t < face.size(); t += 3)
      for (const auto& w : {std::array{1., 1., 1.}, {1., 1., 0.}, {0., 1., 1.}, {1., 0., 1.}}) {
        const double sum = w[0] + w[1] + w[2];
        PlanePoint2 p{0, 0};
        double z = 0;
        for (size_t k = 0; k < 3; ++k) {
          const uint32_t v = face[t + k];
          p = {p[0] + w[k] / sum * roof.points[v][0], p[1] + w[k] / sum * roof.points[v][1]};
          z += w[k] / sum * roof.heights[v];
        }
        ASSERT_NEAR(z, lowest(planes, p), 1e-6) << p[0] << ", " << p[1];
      }
}

TEST(RoofShape, ConcaveFootprintWithCourtyardsTakesEveryShape) {
  // A U with points in the middle of straight edges, two courtyards in its base.
  const PlaneRing u = {{0, 0},   {20, 0},  {40, 0},  {40, 30}, {30, 30},
                       {30, 10}, {10, 10}, {10, 30}, {0, 30},  {0, 15}};
  const auto square = [](double x, double y) {
    return PlaneRing{{x, y}, {x + 6, y}, {x + 6, y + 6}, {x, y + 6}};
  };
  const Footprint fp = make_footprint({u, square(2, 2), square(32, 2)});
  for (const RoofShape shape : kPitched) {
    SCOPED_TRACE(roof_shape_name(shape));
    expect_roof_follows_planes(fp, shape);
  }
}

TEST(RoofShape, EverySohoFootprintTakesEveryShape) {
  const std::string soho =
      std::string(MAQUETTE_SHARED_DIR) + "/data/buildings/london_soho_buildings_wgs84.geojson";
  if (!std::filesystem::exists(soho)) GTEST_SKIP() << soho << " is absent (../shared/data)";
  const SohoScene scene(soho);
  ASSERT_EQ(scene.footprints.size(), 158u);
  for (const VectorFeature& f : scene.footprints) {
    const GeoPoint& first = f.geometry.polygons[0].rings[0][0];
    const GeographicLib::LocalCartesian frame(first.lat, first.lon, 0);
    std::vector<PlaneRing> rings;
    for (const GeoPath& ring : f.geometry.polygons[0].rings) {
      PlaneRing& r = rings.emplace_back();
      for (const GeoPoint& p : ring) {
        double x = 0, y = 0, z = 0;
        frame.Forward(p.lat, p.lon, 0, x, y, z);
        r.push_back({x, y});
      }
    }
    const Footprint fp = make_footprint(rings);
    for (const RoofShape shape : kPitched) {
      SCOPED_TRACE("feature " + std::to_string(f.id) + ", " + roof_shape_name(shape));
      expect_roof_follows_planes(fp, shape);
    }
  }
}

TEST(RoofTags, HeightsFromTheTags) {
  const HeightRules rules{9, 3, 30};
  const auto heights = [&](const nlohmann::json& tags, double run) {
    return part_heights(building_tags(tags, rules), run);
  };
  // height includes the roof: the walls end roof:height below it.
  PartHeights h = heights({{"height", 15}, {"roof:shape", "gabled"}, {"roof:height", 4}}, 5);
  EXPECT_DOUBLE_EQ(h.wall, 11);
  EXPECT_DOUBLE_EQ(h.roof, 4);
  // building:levels count the walls' levels: the roof (2 roof levels of 3 m) on top.
  h = heights({{"building:levels", 4}, {"roof:levels", "2"}, {"roof:shape", "hipped"}}, 5);
  EXPECT_DOUBLE_EQ(h.wall, 12);
  EXPECT_DOUBLE_EQ(h.roof, 6);
  // roof:angle over the run: tan(45 degrees) x 5 m.
  h = heights({{"height", 20}, {"roof:shape", "pyramidal"}, {"roof:angle", 45}}, 5);
  EXPECT_NEAR(h.roof, 5, 1e-12);
  EXPECT_NEAR(h.wall, 15, 1e-12);
  // The default angle (30 degrees), up to one level (3 m), and capped at half the height.
  h = heights({{"roof:shape", "skillion"}}, 4);
  EXPECT_DOUBLE_EQ(h.wall, 9);
  EXPECT_NEAR(h.roof, 4 / std::sqrt(3.0), 1e-12);
  EXPECT_DOUBLE_EQ(heights({{"roof:shape", "gabled"}}, 30).roof, 3);
  EXPECT_NEAR(heights({{"roof:shape", "gabled"}, {"roof:angle", 30}}, 30).roof, 30 / std::sqrt(3.0),
              1e-12);
  h = heights({{"height", 5}, {"roof:shape", "gabled"}}, 30);
  EXPECT_DOUBLE_EQ(h.roof, 2.5);
  // roof:levels = 0: no roof level, the angle decides.
  h = heights({{"height", 20}, {"roof:shape", "gabled"}, {"roof:levels", 0}}, 3);
  EXPECT_NEAR(h.roof, 3 / std::sqrt(3.0), 1e-12);
  // Flat: the roof has no height, whatever its tags.
  h = heights({{"height", 12}, {"roof:height", 3}}, 5);
  EXPECT_DOUBLE_EQ(h.wall, 12);
  EXPECT_DOUBLE_EQ(h.roof, 0);
}

TEST(RoofTags, BadTagsAreNamedAndOtherShapesBuiltFlat) {
  const HeightRules rules;
  const auto message = [&](const nlohmann::json& tags) -> std::string {
    try {
      part_heights(building_tags(tags, rules), 5);
    } catch (const InvalidFootprint& e) {
      return e.what();
    }
    return "accepted";
  };
  EXPECT_EQ(message({{"roof:angle", 95}}),
            "tag roof:angle = 95 is not an angle between 0 and 90 degrees");
  EXPECT_EQ(message({{"roof:direction", "up"}}),
            "tag roof:direction = \"up\" is not degrees or a compass point (N, NNE...)");
  EXPECT_EQ(message({{"roof:orientation", "diagonal"}}),
            "tag roof:orientation = \"diagonal\" is not along or across");
  EXPECT_EQ(message({{"height", 6}, {"roof:height", 6}, {"roof:shape", "gabled"}}),
            "the roof's height 6 m (roof:height or roof:levels) is not below the tag height = 6 m");
  const BuildingTags dome = building_tags({{"roof:shape", "dome"}}, rules);
  EXPECT_EQ(dome.roof, RoofShape::Flat);
  EXPECT_EQ(dome.warning, "roof:shape = \"dome\" is not modelled: built flat");
  EXPECT_EQ(building_tags({{"roof:direction", "SW"}}, rules).direction_deg, 225);
  EXPECT_EQ(building_tags({{"roof:direction", "112.5"}}, rules).direction_deg, 112.5);
}

TEST(RoofTags, FrameFollowsTheLongAxisOrTheDirection) {
  // A 30 x 10 rectangle whose long side runs 30 degrees north of east.
  const double angle = std::numbers::pi / 6;
  const Footprint fp = make_footprint({rectangle(30, 10, angle, 50, 20)});
  BuildingTags tags;
  RoofFrame f = roof_frame(fp, tags);
  EXPECT_NEAR(f.along[0], std::cos(angle), 1e-12);
  EXPECT_NEAR(f.along[1], std::sin(angle), 1e-12);
  EXPECT_NEAR(f.u1 - f.u0, 30, 1e-9);
  EXPECT_NEAR(f.v1 - f.v0, 10, 1e-9);
  tags.across = true;  // the ridge along the short axis
  f = roof_frame(fp, tags);
  EXPECT_NEAR(std::abs(f.along[0]), std::sin(angle), 1e-12);
  EXPECT_NEAR(f.u1 - f.u0, 10, 1e-9);
  // roof:direction 180 (the main face looks south): the ridge runs east-west, a skillion's eave
  // on the south side.
  tags.direction_deg = 180;
  f = roof_frame(fp, tags);
  EXPECT_NEAR(f.across[1], -1, 1e-12);
  const std::vector<RoofPlane> skillion = roof_planes(f, RoofShape::Skillion, {5, 2});
  ASSERT_EQ(skillion.size(), 1u);
  EXPECT_NEAR(skillion[0].a, 0, 1e-12);
  EXPECT_GT(skillion[0].b, 0);  // rising northwards
}

}  // namespace
}  // namespace maquette::structures
