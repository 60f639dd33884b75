// Parsing of feature strokes: valid strokes, other tools left alone, and errors that name the
// feature and the field.
#include "../stroke.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace maquette::deform
