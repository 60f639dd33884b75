// Parsing of feature strokes: valid strokes, other tools left alone, and errors that name the
// feature and the field: malformed attributes, control curves that cross, touch, overlap or turn
// back over themselves (placed in metres by GeographicLib), cross sections that disagree with the
// curve at offset 0.
#include "../stroke.h"

#include <gtest/gtest.h>

#include <GeographicLib/LocalCartesian.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "core/enu_frame.h"
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

// The self-contact check as first written, every pair of segments tried in order (kept as the
// oracle of the sweep in stroke.cpp): the message of its first fault, "" when none.
std::string all_pairs_fault(const std::vector<std::array<double, 2>>& at) {
  using P = std::array<double, 2>;
  const auto minus = [](P a, P b) { return P{a[0] - b[0], a[1] - b[1]}; };
  const auto dot = [](P a, P b) { return a[0] * b[0] + a[1] * b[1]; };
  const auto cross = [](P a, P b) { return a[0] * b[1] - a[1] * b[0]; };
  const auto point_segment = [&](P p, P a, P b) {
    const P ab = minus(b, a), ap = minus(p, a);
    const double t = std::clamp(dot(ap, ab) / dot(ab, ab), 0.0, 1.0);
    return std::hypot(ap[0] - t * ab[0], ap[1] - t * ab[1]);
  };
  const auto segment_segment = [&](P a, P b, P c, P d) {
    const double d1 = cross(minus(b, a), minus(c, a)), d2 = cross(minus(b, a), minus(d, a));
    const double d3 = cross(minus(d, c), minus(a, c)), d4 = cross(minus(d, c), minus(b, c));
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
      return 0.0;
    return std::min({point_segment(a, c, d), point_segment(b, c, d), point_segment(c, a, b),
                     point_segment(d, a, b)});
  };
  std::vector<size_t> seg;
  for (size_t i = 0; i + 1 < at.size(); ++i)
    if (at[i] != at[i + 1]) seg.push_back(i);
  const auto fault = [&](size_t i, size_t j, const std::string& what) {
    return "inputs.strokes: feature 1: the control curve " + what + " (segments " +
           std::to_string(seg[i] + 1) + " and " + std::to_string(seg[j] + 1) + ")";
  };
  for (size_t i = 0; i < seg.size(); ++i)
    for (size_t j = i + 1; j < seg.size(); ++j) {
      const P a = at[seg[i]], b = at[seg[i] + 1], c = at[seg[j]], d = at[seg[j] + 1];
      if (j == i + 1) {
        if (dot(minus(b, a), minus(d, c)) < 0 &&
            std::min(point_segment(d, a, b), point_segment(a, c, d)) <= kSelfContactM)
          return fault(i, j, "turns back over itself");
      } else if (segment_segment(a, b, c, d) <= kSelfContactM) {
        return fault(i, j, "crosses itself");
      }
    }
  return "";
}

// Random control curves (walks of 3 to 300 vertices; some ending within 0 to 2 cm of an earlier
// segment, some turning back within 0 to 2 cm, some seldom meeting themselves): the sweep names the
// same fault as every pair tried in order, or none when it finds none.
TEST(FeatureStrokes, SelfContactSweepAgreesWithAllPairsOnRandomCurves) {
  std::mt19937_64 random(16);
  std::uniform_real_distribution<double> unit(0, 1);
  const LonLat origin{-113.0, 37.2};
  const EnuFrame plane({origin.lon, origin.lat, 0});
  std::map<std::string, int> kinds;
  for (int trial = 0; trial < 3000; ++trial) {
    const int points = 3 + int(unit(random) * (trial % 10 == 0 ? 298 : 40));
    // 0: a free walk, 1: gentle turns (seldom meeting itself), 2: ending near an earlier
    // segment, 3: gentle turns then back along the last segment
    const int kind = trial % 4;
    std::vector<LonLat> curve{origin};
    double heading = unit(random) * 2 * std::numbers::pi;
    for (int k = 1; k < points; ++k) {
      heading +=
          kind == 1 || kind == 3 ? 0.3 * (unit(random) - 0.5) : 2 * std::numbers::pi * unit(random);
      const auto [x, y, z] = plane.to_enu(curve.back().lon, curve.back().lat);
      const double step = 0.5 + 30 * unit(random);
      const GeodeticPoint next =
          plane.to_geodetic(x + step * std::cos(heading), y + step * std::sin(heading), z);
      curve.push_back({next.lon, next.lat});
    }
    std::vector<std::array<double, 2>> at;
    for (const LonLat& p : curve) {
      const auto [x, y, z] = plane.to_enu(p.lon, p.lat);
      at.push_back({x, y});
    }
    if (kind == 2 && points > 3) {  // a last vertex 0 to 2 cm beside an earlier segment
      const size_t k = size_t(unit(random) * double(points - 3));
      const double t = unit(random), d = 0.02 * unit(random);
      const double ex = at[k + 1][0] - at[k][0], ey = at[k + 1][1] - at[k][1];
      const double length = std::hypot(ex, ey);
      const std::array q{at[k][0] + t * ex - d * ey / length, at[k][1] + t * ey + d * ex / length};
      const GeodeticPoint g = plane.to_geodetic(q[0], q[1], 0);
      curve.push_back({g.lon, g.lat});
    } else if (kind == 3) {  // back along the last segment, 0 to 2 cm beside it
      const auto& a = at[at.size() - 2];
      const auto& b = at.back();
      const double d = 0.02 * unit(random), length = std::hypot(b[0] - a[0], b[1] - a[1]);
      const GeodeticPoint g =
          plane.to_geodetic(a[0] + 0.5 * (b[0] - a[0]) - d * (b[1] - a[1]) / length,
                            a[1] + 0.5 * (b[1] - a[1]) + d * (b[0] - a[0]) / length, 0);
      curve.push_back({g.lon, g.lat});
    }
    at.clear();
    for (const LonLat& p : curve) {
      const auto [x, y, z] = plane.to_enu(p.lon, p.lat);
      at.push_back({x, y});
    }
    VectorFeature f = line(1, {{"tool", "feature"}, {"cross_section", {{-5, 1}, {0, 0}, {5, 1}}}});
    f.geometry.lines[0].clear();
    for (const LonLat& p : curve) f.geometry.lines[0].push_back({p.lon, p.lat, NAN});
    const std::string expected = all_pairs_fault(at);
    ASSERT_EQ(error_of(f), expected) << "trial " << trial;
    ++kinds[expected.empty()                                   ? "none"
            : expected.find("turns back") != std::string::npos ? "turns back"
                                                               : "crosses"];
  }
  std::printf("random curves: %d without contact, %d crossing, %d turning back\n", kinds["none"],
              kinds["crosses"], kinds["turns back"]);
  EXPECT_GT(kinds["none"], 200);
  EXPECT_GT(kinds["crosses"], 200);
  EXPECT_GT(kinds["turns back"], 200);
}

}  // namespace
}  // namespace maquette::deform
