// Parsing of feature strokes: valid strokes, other tools left alone, and errors that name the
// feature and the field: malformed attributes, control curves that cross, touch, overlap or turn
// back over themselves (placed in metres by GeographicLib), cross sections that disagree with the
// curve at offset 0.
#include "../stroke.h"

#include <gtest/gtest.h>

#include <GeographicLib/LocalCartesian.hpp>

#include "core/error.h"

namespace maquette::deform {
namespace {

VectorFeature line(int64_t id, nlohmann::json attributes, bool with_z = false) {
  VectorFeature f;
  f.id = id;
  f.geometry.type = GeometryType::LineString;
  f.geometry.has_z = with_z;
  f.geometry.lines = {{{10, 45, with_z ? 100 : NAN}, {10.01, 45, with_z ? 90 : NAN}}};
  f.attributes = std::move(attributes);
  return f;
}

std::string error_of(const VectorFeature& f) {
  try {
    feature_strokes({&f}, "strokes");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(FeatureStrokes, ParsesCurveProfileAndCrossSection) {
  const VectorFeature river = line(3, {{"tool", "feature"},
                                       {"cross_section", {{-20, 5}, {-5, 0}, {5, 0}, {20, 5}}},
                                       {"profile", {{0, 800}, {900, 790}}}});
  const VectorFeature lake = line(4, {{"tool", "water"}});
  const auto strokes = feature_strokes({&river, &lake}, "strokes");
  ASSERT_EQ(strokes.size(), 1u);
  EXPECT_EQ(strokes[0].id, 3);
  EXPECT_EQ(strokes[0].curve.size(), 2u);
  EXPECT_TRUE(strokes[0].z.empty());
  EXPECT_EQ(strokes[0].cross_section.size(), 4u);
  EXPECT_DOUBLE_EQ(piecewise_linear(strokes[0].cross_section, -12.5), 2.5);
  EXPECT_DOUBLE_EQ(piecewise_linear(strokes[0].cross_section, 30), 5);
  EXPECT_DOUBLE_EQ(piecewise_linear(strokes[0].profile, 450), 795);

  const VectorFeature road =
      line(5, {{"tool", "feature"}, {"cross_section", {{-1, 0}, {1, 0}}}}, true);
  const auto with_z = feature_strokes({&road}, "strokes");
  ASSERT_EQ(with_z[0].z.size(), 2u);
  EXPECT_EQ(with_z[0].z[1], 90);
}

TEST(FeatureStrokes, ErrorsNameTheFeatureAndField) {
  EXPECT_EQ(error_of(line(7, {{"tool", "feature"}})),
            "inputs.strokes: feature 7: no cross_section attribute ([[offset_m, dz_m]...])");
  EXPECT_EQ(error_of(line(7, {{"tool", "feature"}, {"cross_section", {{1, 0}, {-1, 0}}}})),
            "inputs.strokes: feature 7: cross_section[1]: its first value -1 does not increase on "
            "the previous pair's");
  EXPECT_EQ(
      error_of(line(7, {{"tool", "feature"}, {"cross_section", {{1, "a"}, {2, 0}}}})),
      "inputs.strokes: feature 7: cross_section[0]: expected [number, number], got [1,\"a\"]");
  EXPECT_EQ(error_of(line(8,
                          {{"tool", "feature"},
                           {"cross_section", {{-1, 0}, {1, 0}}},
                           {"profile", {{0, 1}, {10, 2}}}},
                          true)),
            "inputs.strokes: feature 8: both Z values and a profile give the curve's elevation; "
            "keep one");
  VectorFeature polygon = line(9, {{"tool", "feature"}});
  polygon.geometry.type = GeometryType::Polygon;
  EXPECT_EQ(error_of(polygon),
            "inputs.strokes: feature 9: a stroke of tool 'feature' is a LineString (the control "
            "curve)");
  VectorFeature point_like = line(10, {{"tool", "feature"}, {"cross_section", {{-1, 0}, {1, 0}}}});
  point_like.geometry.lines[0][1] = point_like.geometry.lines[0][0];
  EXPECT_EQ(error_of(point_like),
            "inputs.strokes: feature 10: the control curve needs at least two distinct points");
}

// A stroke through points given in metres east and north of (10, 45).
VectorFeature curve(int64_t id, const std::vector<std::array<double, 2>>& metres) {
  const GeographicLib::LocalCartesian plane(45, 10, 0);
  VectorFeature f = line(id, {{"tool", "feature"}, {"cross_section", {{-5, 0}, {5, 0}}}});
  f.geometry.lines[0].clear();
  for (const auto& [e, n] : metres) {
    double lat = 0, lon = 0, h = 0;
    plane.Reverse(e, n, 0, lat, lon, h);
    f.geometry.lines[0].push_back({lon, lat, NAN});
  }
  return f;
}

TEST(FeatureStrokes, CurvesTouchingOverlappingOrTurningBackOnThemselvesAreErrors) {
  // Segment 5 runs back along segment 1 (collinear, overlapping over 50 m), touching nothing
  // else: all three cross products of the old test were 0.
  EXPECT_EQ(error_of(curve(20, {{100, 0}, {0, 0}, {0, 30}, {150, 30}, {150, 0}, {50, 0}})),
            "inputs.strokes: feature 20: the control curve crosses itself (segments 1 and 5)");
  // Segment 2 turns straight back over segment 1; a repeated point does not hide it and
  // segments keep their LineString numbers.
  EXPECT_EQ(error_of(curve(21, {{0, 0}, {100, 0}, {100, 0}, {40, 0}})),
            "inputs.strokes: feature 21: the control curve turns back over itself (segments 1 and "
            "3)");
  // Passing 5 mm from itself counts as touching (kSelfContactM), 5 cm does not.
  EXPECT_EQ(error_of(curve(22, {{0, 0}, {100, 0}, {100, 30}, {50, 30}, {50, 0.005}})),
            "inputs.strokes: feature 22: the control curve crosses itself (segments 1 and 4)");
  EXPECT_EQ(error_of(curve(23, {{0, 0}, {100, 0}, {100, 30}, {50, 30}, {50, 0.05}})), "");
  // A hairpin that turns back without lying on itself, and a straight run with a repeated point.
  EXPECT_EQ(error_of(curve(24, {{0, 0}, {100, 0}, {0, 20}})), "");
  EXPECT_EQ(error_of(curve(25, {{0, 0}, {50, 0}, {50, 0}, {100, 0}})), "");
}

TEST(FeatureStrokes, CrossSectionMustHaveDzZeroAtTheCurve) {
  EXPECT_EQ(
      error_of(line(12, {{"tool", "feature"}, {"cross_section", {{-5, 1}, {5, 2}}}})),
      "inputs.strokes: feature 12: cross_section: dz at offset 0 is 1.5 m, but the control "
      "curve's elevation holds there: make it 0 (and move the curve, its Z or its profile, to "
      "where the section meets it)");
  // A cliff's drop just right of the curve, and a section on one side only, away from the curve.
  EXPECT_EQ(error_of(line(13, {{"tool", "feature"},
                               {"cross_section", {{-30, 0}, {0, 0}, {2, -25}, {30, -25}}}})),
            "");
  EXPECT_EQ(error_of(line(14, {{"tool", "feature"}, {"cross_section", {{2, -1}, {10, -3}}}})), "");
}

}  // namespace
}  // namespace maquette::deform
