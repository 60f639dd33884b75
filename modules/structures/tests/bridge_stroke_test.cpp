// Bridge strokes (bridge_stroke.h) read from features: the two edges, the second turned round when
// drawn from the other bank, the thickness; and what is refused, naming the feature and field.
#include "../bridge_stroke.h"

#include <gtest/gtest.h>

#include "core/error.h"

namespace maquette::structures {
namespace {

VectorFeature feature(std::vector<GeoPath> lines, nlohmann::json attributes) {
  VectorFeature f;
  f.id = 7;
  f.geometry.type = GeometryType::MultiLineString;
  f.geometry.lines = std::move(lines);
  f.attributes = std::move(attributes);
  f.attributes["tool"] = "bridge";
  return f;
}

const GeoPath kSouth = {{7.0, 46.0}, {7.01, 46.0}}, kNorth = {{7.0, 46.0001}, {7.01, 46.0001}};

void expect_error(const VectorFeature& f, const std::string& message) {
  try {
    bridge_stroke(f, 1);
    ADD_FAILURE() << "accepted; expected: " << message;
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "feature 7 (tool bridge): " + message);
  }
}

TEST(BridgeStroke, EdgesAndThickness) {
  const VectorFeature f = feature({kSouth, kNorth}, {{"thickness_m", 2.5}});
  EXPECT_TRUE(is_bridge_stroke(f));
  const BridgeStroke b = bridge_stroke(f, 1);
  EXPECT_EQ(b.id, 7);
  EXPECT_EQ(b.thickness_m, 2.5);
  EXPECT_EQ(b.second_edge.front().lon, 7.0);
  EXPECT_EQ(bridge_stroke(feature({kSouth, kNorth}, nlohmann::json::object()), 1.25).thickness_m,
            1.25);
  // Drawn from the other bank: turned round, its first point beside the first edge's.
  const BridgeStroke turned =
      bridge_stroke(feature({kSouth, {kNorth[1], kNorth[0]}}, nlohmann::json::object()), 1);
  EXPECT_EQ(turned.second_edge.front().lon, 7.0);
  EXPECT_EQ(turned.second_edge.back().lon, 7.01);
}

TEST(BridgeStroke, BadStrokesAreNamed) {
  expect_error(feature({kSouth}, nlohmann::json::object()),
               "geometry: a MultiLineString of 1 part(s), not a MultiLineString of the deck's two "
               "edges");
  VectorFeature line = feature({kSouth}, nlohmann::json::object());
  line.geometry.type = GeometryType::LineString;
  expect_error(
      line, "geometry: a LineString of 1 part(s), not a MultiLineString of the deck's two edges");
  expect_error(feature({kSouth, {kNorth[0], kNorth[0]}}, nlohmann::json::object()),
               "geometry: edge 2 has 2 point(s) and fewer than 2 distinct ones: an edge needs 2");
  expect_error(feature({{kSouth[0]}, kNorth}, nlohmann::json::object()),
               "geometry: edge 1 has 1 point(s) and fewer than 2 distinct ones: an edge needs 2");
  expect_error(feature({kSouth, kNorth}, {{"thickness_m", 0}}),
               "thickness_m: 0 is not a positive number of metres up to 100");
  expect_error(feature({kSouth, kNorth}, {{"thickness_m", "1 m"}}),
               "thickness_m: \"1 m\" is not a positive number of metres up to 100");
  expect_error(feature({kSouth, kNorth}, {{"thickness_m", 250}}),
               "thickness_m: 250 is not a positive number of metres up to 100");
}

}  // namespace
}  // namespace maquette::structures
