// structures.place's fit against independent oracles: area moments of unions of axis-aligned
// rectangles integrated in closed form (integral of x^a y^b over a box is separable), and
// thousands of trials whose transform is known: a footprint turned, scaled and moved, its outline
// drawn as a stroke with every point perturbed, then fitted back.
#include "../place_stroke.h"

#include <gtest/gtest.h>

#include <GeographicLib/Geodesic.hpp>
#include <GeographicLib/LocalCartesian.hpp>
#include <GeographicLib/PolygonArea.hpp>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <numbers>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/splitmix64.h"

namespace maquette::structures {
namespace {

constexpr double kPi = std::numbers::pi;

struct Box {
  double x0, y0, x1, y1;
};

// Integral of (x - cx)^a (y - cy)^b over the disjoint boxes.
double box_moment(const std::vector<Box>& boxes, int a, int b, double cx, double cy) {
  double sum = 0;
  for (const Box& r : boxes) {
    const double ix = (std::pow(r.x1 - cx, a + 1) - std::pow(r.x0 - cx, a + 1)) / (a + 1);
    const double iy = (std::pow(r.y1 - cy, b + 1) - std::pow(r.y0 - cy, b + 1)) / (b + 1);
    sum += ix * iy;
  }
  return sum;
}

// The area axes of disjoint boxes in closed form, the major axis's sign taken from `angle`.
AreaAxes box_axes(const std::vector<Box>& boxes) {
  AreaAxes axes;
  axes.area = box_moment(boxes, 0, 0, 0, 0);
  const double cx = box_moment(boxes, 1, 0, 0, 0) / axes.area;
  const double cy = box_moment(boxes, 0, 1, 0, 0) / axes.area;
  axes.centroid = {cx, cy};
  const auto m = [&](int a, int b) { return box_moment(boxes, a, b, cx, cy) / axes.area; };
  // Eigenvalues of the 2x2 covariance by its characteristic polynomial.
  const double t = m(2, 0) + m(0, 2), d = m(2, 0) * m(0, 2) - m(1, 1) * m(1, 1);
  axes.major_var = t / 2 + std::sqrt(t * t / 4 - d);
  axes.minor_var = t / 2 - std::sqrt(t * t / 4 - d);
  // The major eigenvector (m11, major - m20), or the x axis when the covariance is diagonal.
  axes.angle = m(1, 1) == 0 ? (m(2, 0) >= m(0, 2) ? 0 : kPi / 2)
                            : std::atan(-(m(2, 0) - axes.major_var) / m(1, 1));
  const auto skew = [&](double c, double s, double var) {
    const double u3 = c * c * c * m(3, 0) + 3 * c * c * s * m(2, 1) + 3 * c * s * s * m(1, 2) +
                      s * s * s * m(0, 3);
    return u3 / std::pow(var, 1.5);
  };
  const double c = std::cos(axes.angle), s = std::sin(axes.angle);
  axes.skew_major = skew(c, s, axes.major_var);
  axes.skew_minor = skew(-s, c, axes.minor_var);
  return axes;
}

// An L: the box [0, w] x [0, h] without its top-right corner of cut_w x cut_h, counter-clockwise.
Ring l_ring(double w, double h, double cut_w, double cut_h) {
  return {{0, 0}, {w, 0}, {w, h - cut_h}, {w - cut_w, h - cut_h}, {w - cut_w, h}, {0, h}};
}
std::vector<Box> l_boxes(double w, double h, double cut_w, double cut_h) {
  return {{0, 0, w, h - cut_h}, {0, h - cut_h, w - cut_w, h}};
}

void expect_axes_near(const AreaAxes& got, const AreaAxes& want) {
  const double size = std::sqrt(want.major_var);
  EXPECT_NEAR(got.area, want.area, 1e-9 * want.area);
  EXPECT_NEAR(got.centroid[0], want.centroid[0], 1e-9 * size);
  EXPECT_NEAR(got.centroid[1], want.centroid[1], 1e-9 * size);
  EXPECT_NEAR(got.major_var, want.major_var, 1e-9 * want.major_var);
  EXPECT_NEAR(got.minor_var, want.minor_var, 1e-9 * want.major_var);
  EXPECT_NEAR(std::remainder(got.angle - want.angle, kPi), 0, 1e-9);
  // The skewness follows the axis's sign: compare in the oracle's sense.
  const double sign = std::cos(got.angle - want.angle) > 0 ? 1 : -1;
  EXPECT_NEAR(sign * got.skew_major, want.skew_major, 1e-9);
  EXPECT_NEAR(sign * got.skew_minor, want.skew_minor, 1e-9);
}

Ring transformed(const Ring& ring, double rotation, double scale, Point2 offset) {
  const double c = std::cos(rotation), s = std::sin(rotation);
  Ring out;
  for (const Point2& p : ring) {
    out.push_back(
        {scale * (c * p[0] - s * p[1]) + offset[0], scale * (s * p[0] + c * p[1]) + offset[1]});
  }
  return out;
}

TEST(PlaceAreaAxes, RectangleMatchesClosedFormAnywhere) {
  const Ring rect{{0, 0}, {30, 0}, {30, 12}, {0, 12}};
  const AreaAxes want = box_axes({{0, 0, 30, 12}});
  EXPECT_DOUBLE_EQ(want.major_var, 30.0 * 30 / 12);
  expect_axes_near(area_axes(rect, "rect"), want);
  // Far from the origin (UTM-like coordinates), turned: the same moments, the centroid moved.
  const double turn = 0.7;
  const Point2 shift{512345.25, 5412345.5};
  const AreaAxes moved = area_axes(transformed(rect, turn, 1, shift), "rect");
  EXPECT_NEAR(moved.major_var, want.major_var, 1e-8 * want.major_var);
  EXPECT_NEAR(moved.minor_var, want.minor_var, 1e-8 * want.major_var);
  EXPECT_NEAR(std::remainder(moved.angle - turn, kPi), 0, 1e-9);
  const Point2 centre = transformed({want.centroid}, turn, 1, shift)[0];
  EXPECT_NEAR(moved.centroid[0], centre[0], 1e-6);
  EXPECT_NEAR(moved.centroid[1], centre[1], 1e-6);
}

TEST(PlaceAreaAxes, LShapeMatchesClosedFormEitherOrientation) {
  for (const auto& [w, h, cw, ch] :
       std::vector<std::array<double, 4>>{{40, 25, 22, 10}, {20, 35, 8, 20}, {30, 30, 12, 12}}) {
    SCOPED_TRACE(std::to_string(w) + " x " + std::to_string(h));
    const AreaAxes want = box_axes(l_boxes(w, h, cw, ch));
    Ring ring = l_ring(w, h, cw, ch);
    expect_axes_near(area_axes(ring, "L"), want);
    std::reverse(ring.begin(), ring.end());
    ring.push_back(ring.front());  // clockwise and explicitly closed
    expect_axes_near(area_axes(ring, "L"), want);
  }
}

TEST(PlaceAreaAxes, AreaNotVerticesDecidesTheAxes) {
  // A 20 x 10 rectangle whose short sides carry many extra collinear points: their vertex
  // covariance would turn the major axis to y, the area's stays on x.
  Ring ring{{0, 0}, {20, 0}};
  for (int i = 1; i < 50; ++i) ring.push_back({20, 10.0 * i / 50});
  ring.push_back({20, 10});
  ring.push_back({0, 10});
  for (int i = 49; i > 0; --i) ring.push_back({0, 10.0 * i / 50});
  const AreaAxes axes = area_axes(ring, "dense");
  EXPECT_NEAR(axes.angle, 0, 1e-12);
  EXPECT_NEAR(axes.major_var, 400.0 / 12, 1e-9);
}

TEST(PlaceAreaAxes, DegenerateRingsNameWhere) {
  const auto message = [](const Ring& ring) {
    try {
      area_axes(ring, "feature 7: stroke");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message({{0, 0}, {1, 1}, {0, 0}}),
            "feature 7: stroke: a ring needs at least three distinct points, it has 2");
  EXPECT_EQ(message({{0, 0}, {1, 1}, {2, 2}, {3, 3}}),
            "feature 7: stroke: the ring has no area (its points are collinear or repeated)");
  EXPECT_EQ(message({{0, 0}, {1, NAN}, {0, 1}}),
            "feature 7: stroke: point 1 has a non-finite coordinate");
}

// Reproducible uniform numbers in [0, 1) from SplitMix64 (the same bits on every platform).
class Uniform {
 public:
  explicit Uniform(uint64_t seed) : state_(seed) {}
  double operator()() { return static_cast<double>(splitmix64_next(state_) >> 11) * 0x1p-53; }
  double operator()(double lo, double hi) { return lo + (hi - lo) * (*this)(); }

 private:
  uint64_t state_;
};

// The outline of `ring` as a drawn stroke: `count` points evenly spaced along its perimeter from
// a random start (corners are cut, as a hand cuts them), each moved by a uniform random vector of
// length <= `noise`.
Ring drawn_stroke(const Ring& ring, int count, double noise, Uniform& uniform) {
  std::vector<double> at{0};
  for (size_t i = 0; i < ring.size(); ++i) {
    const Point2& a = ring[i];
    const Point2& b = ring[(i + 1) % ring.size()];
    at.push_back(at.back() + std::hypot(b[0] - a[0], b[1] - a[1]));
  }
  const double start = uniform(0, at.back());
  Ring stroke;
  for (int k = 0; k < count; ++k) {
    const double d = std::fmod(start + at.back() * k / count, at.back());
    const size_t i = std::upper_bound(at.begin(), at.end(), d) - at.begin() - 1;
    const Point2& a = ring[i];
    const Point2& b = ring[(i + 1) % ring.size()];
    const double t = (d - at[i]) / (at[i + 1] - at[i]);
    const double r = noise * std::sqrt(uniform()), phi = uniform(0, 2 * kPi);
    stroke.push_back({a[0] + t * (b[0] - a[0]) + r * std::cos(phi),
                      a[1] + t * (b[1] - a[1]) + r * std::sin(phi)});
  }
  return stroke;
}

struct Errors {
  std::vector<double> rotation_deg, scale_percent, offset_percent;
  int undecided = 0;
};

double quantile(std::vector<double> values, double q) {
  std::sort(values.begin(), values.end());
  return values[static_cast<size_t>(q * (values.size() - 1))];
}

double max_of(const std::vector<double>& values) { return quantile(values, 1); }

void report(const std::string& name, const std::vector<double>& values) {
  std::cout << name << ": median " << quantile(values, 0.5) << ", p99 " << quantile(values, 0.99)
            << ", max " << max_of(values) << " (" << values.size() << " trials)\n";
}

// Footprint trials: `make` returns a base ring (model metres) of aspect >= 1.3; its outline is
// turned, scaled and moved by a known transform, drawn as a stroke of `points` points with noise
// of 2 % of the footprint's longer side, and fitted. Rotation is compared modulo `period`.
template <class Make>
Errors run_trials(int trials, int points, double period, uint64_t seed, bool refine, Make make) {
  Uniform uniform(seed);
  Errors errors;
  for (int n = 0; n < trials; ++n) {
    double size = 0;
    const Ring base = make(uniform, size);
    const double rotation = uniform(-kPi, kPi), scale = std::exp(uniform(std::log(0.5), 1));
    const Point2 offset{uniform(-1000, 1000), uniform(-1000, 1000)};
    const Ring truth = transformed(base, rotation, scale, offset);
    const Ring stroke = drawn_stroke(truth, points, 0.02 * scale * size, uniform);
    PlaceOptions options;
    options.refine = refine;
    const PlaceFit fit = fit_place(stroke, base, options, "trial " + std::to_string(n));
    errors.undecided += fit.half_turn_decided ? 0 : 1;
    errors.rotation_deg.push_back(std::abs(std::remainder(fit.rotation - rotation, period)) * 180 /
                                  kPi);
    errors.scale_percent.push_back(std::abs(fit.scale / scale - 1) * 100);
    // Where the base's own corners land, against where they should.
    double worst = 0;
    const Ring placed = transformed(base, fit.rotation, fit.scale, fit.offset);
    for (size_t i = 0; i < base.size(); ++i) {
      worst = std::max(worst, std::hypot(placed[i][0] - truth[i][0], placed[i][1] - truth[i][1]));
    }
    if (period < 2 * kPi) worst = 0;  // a symmetric footprint's half turn moves corners, not it
    errors.offset_percent.push_back(worst / (scale * size) * 100);
  }
  return errors;
}

// A rectangle 10..60 m long, of aspect 1.3..3.
Ring random_rectangle(Uniform& uniform, double& size) {
  size = uniform(10, 60);
  const double width = size / uniform(1.3, 3);
  return {{0, 0}, {size, 0}, {size, width}, {0, width}};
}

// An L 10..60 m long whose area's axes have an aspect (sqrt of the variance ratio) >= 1.3.
Ring random_l_shape(Uniform& uniform, double& size) {
  for (;;) {
    const double w = uniform(10, 60), h = w * uniform(0.3, 1.2);
    const double cw = w * uniform(0.3, 0.7), ch = h * uniform(0.3, 0.7);
    const AreaAxes axes = box_axes(l_boxes(w, h, cw, ch));
    if (axes.major_var / axes.minor_var >= 1.3 * 1.3) {
      size = std::max(w, h);
      return l_ring(w, h, cw, ch);
    }
  }
}

// The refinement does better than the moments it starts from, at the median and the 99th
// percentile of the rotation error.
void expect_refinement_helps(const Errors& refined, const Errors& moments) {
  for (const double q : {0.5, 0.99}) {
    EXPECT_LT(quantile(refined.rotation_deg, q), quantile(moments.rotation_deg, q)) << q;
  }
}

// Strokes of 32 to 256 points: the error is the noise's, falling as 1 / sqrt(points). Every
// stroke keeps the scale within 3 %; the rotation is within 1 degree at the 99th percentile from
// 64 points and in every trial from 128 points (a point every 1.6 m around 60 m x 46 m).
template <class Make>
void expect_bounds(const std::string& name, double period, uint64_t seed, Make make) {
  for (const int points : {32, 64, 128, 256}) {
    SCOPED_TRACE(points);
    const Errors e = run_trials(5000, points, period, seed, true, make);
    const std::string what = name + ", " + std::to_string(points) + " points, ";
    report(what + "rotation error (deg)", e.rotation_deg);
    report(what + "scale error (%)", e.scale_percent);
    if (period > kPi) report(what + "corner position error (% of length)", e.offset_percent);
    EXPECT_LE(max_of(e.scale_percent), 3.0);
    EXPECT_LE(max_of(e.offset_percent), 3.0);
    if (points >= 64) {
      EXPECT_LE(quantile(e.rotation_deg, 0.99), 1.0);
    }
    if (points >= 128) {
      EXPECT_LE(max_of(e.rotation_deg), 1.0);
    }
    // Measured modulo a full turn for an L: a wrong half turn would show as 180 degrees.
    EXPECT_EQ(e.undecided, period > kPi ? 0 : 5000);
    if (points == 64) {
      const Errors moments = run_trials(5000, points, period, seed, false, make);
      report(what + "moments alone, rotation error (deg)", moments.rotation_deg);
      report(what + "moments alone, scale error (%)", moments.scale_percent);
      expect_refinement_helps(e, moments);
    }
  }
}

// A rectangle is centrally symmetric: no skewness can tell its half turns apart (all undecided).
TEST(PlaceFit, RectanglesOfAspectAtLeast1_3WithTwoPercentNoise) {
  expect_bounds("rectangles", kPi, 1, random_rectangle);
}

TEST(PlaceFit, LShapesOfAspectAtLeast1_3WithTwoPercentNoise) {
  expect_bounds("L-shapes", 2 * kPi, 2, random_l_shape);
}

TEST(PlaceFit, SquaresAndDiscsAreAmbiguous) {
  Uniform uniform(3);
  std::vector<Ring> shapes{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  Ring disc;
  for (int i = 0; i < 40; ++i)
    disc.push_back({std::cos(2 * kPi * i / 40), std::sin(2 * kPi * i / 40)});
  shapes.push_back(disc);
  const Ring base{{0, 0}, {20, 0}, {20, 8}, {0, 8}};
  double highest = 0;
  for (int n = 0; n < 2000; ++n) {
    const Ring& shape = shapes[n % 2];
    const double scale = uniform(5, 60);
    const Ring truth = transformed(shape, uniform(-kPi, kPi), scale, {uniform(-99, 99), 0});
    const Ring stroke = drawn_stroke(truth, 32, 0.02 * scale, uniform);
    const AreaAxes axes = area_axes(stroke, "stroke");
    highest = std::max(highest, axes.major_var / axes.minor_var);
    try {
      fit_place(stroke, base, {}, "structures.place: feature 5");
      ADD_FAILURE() << "trial " << n << " fitted an ambiguous stroke";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(
                    "structures.place: feature 5: the stroke's principal axes are nearly equal"),
                std::string::npos)
          << e.what();
    }
  }
  std::cout << "squares and discs, highest variance ratio " << highest << "\n";
  EXPECT_LT(highest, PlaceOptions{}.min_axis_ratio);
}

// A rectangle's half turn stays undecided even when its base is as noisy as its stroke (a base
// from a model's vertices is not exactly symmetric): noise alone stays below min_skew_product.
TEST(PlaceFit, NoisySymmetricBaseLeavesTheHalfTurnUndecided) {
  Uniform uniform(5);
  double highest = 0;
  for (int n = 0; n < 2000; ++n) {
    double size = 0;
    const Ring rect = random_rectangle(uniform, size);
    const Ring base = drawn_stroke(rect, 32, 0.02 * size, uniform);
    const Ring stroke =
        drawn_stroke(transformed(rect, uniform(-kPi, kPi), 2, {}), 32, 0.04 * size, uniform);
    const AreaAxes b = area_axes(base, "base"), s = area_axes(stroke, "stroke");
    highest =
        std::max(highest, std::abs(b.skew_major * s.skew_major + b.skew_minor * s.skew_minor));
    EXPECT_FALSE(fit_place(stroke, base, {}, "trial").half_turn_decided) << n;
  }
  std::cout << "noisy rectangles, highest skewness product " << highest << "\n";
}

TEST(PlaceFit, SymmetricBaseIsAmbiguousToo) {
  const Ring square{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  const Ring stroke{{0, 0}, {30, 0}, {30, 10}, {0, 10}};
  try {
    fit_place(stroke, square, {}, "structures.place: feature 1");
    ADD_FAILURE() << "a square base was given a heading";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(),
                 "structures.place: feature 1: the base footprint's principal axes are nearly "
                 "equal (variance ratio 1 < 1.25): its heading is ambiguous; give the heading "
                 "explicitly");
  }
}

TEST(PlaceFit, ExplicitHeadingOverridesTheAxes) {
  const Ring base = l_ring(30, 20, 12, 8);
  const AreaAxes b = box_axes(l_boxes(30, 20, 12, 8));
  // A disc-like stroke has no heading of its own: the given one is used.
  Ring disc;
  for (int i = 0; i < 90; ++i)
    disc.push_back({5 + 20 * std::cos(i * kPi / 45), 7 + 20 * std::sin(i * kPi / 45)});
  PlaceOptions options;
  options.rotation = rotation_from_heading_deg(90);  // the model's +y to the east
  const PlaceFit fit = fit_place(disc, base, options, "feature 2");
  EXPECT_NEAR(fit.rotation, -kPi / 2, 1e-15);
  const AreaAxes d = area_axes(disc, "disc");
  EXPECT_NEAR(fit.scale, std::sqrt(d.area / b.area), 1e-12);
  // The base's centroid lands on the stroke's, the model's +y points east.
  const Ring placed =
      transformed({b.centroid, {0, 0}, {0, 1}}, fit.rotation, fit.scale, fit.offset);
  EXPECT_NEAR(placed[0][0], d.centroid[0], 1e-9);
  EXPECT_NEAR(placed[0][1], d.centroid[1], 1e-9);
  EXPECT_NEAR((placed[2][0] - placed[1][0]) / fit.scale, 1, 1e-12);
  EXPECT_NEAR(placed[2][1] - placed[1][1], 0, 1e-12);
  // On an elongated stroke too, the given heading wins over the axes'.
  options.rotation = 2.5;
  const Ring stroke = transformed(base, 0.4, 2, {100, 50});
  EXPECT_NEAR(fit_place(stroke, base, options, "feature 3").rotation, 2.5, 1e-15);
  const PlaceFit axes_fit = fit_place(stroke, base, {}, "feature 3");
  EXPECT_NEAR(axes_fit.rotation, 0.4, 1e-12);
  EXPECT_NEAR(axes_fit.axis_ratio, b.major_var / b.minor_var, 1e-9);
}

// A stroke of the footprint's corners only (as a user clicks a polygon, not a hand-drawn ring):
// the refinement sees the outline, not four points (it once gave scale 24,699 on a rectangle).
TEST(PlaceFit, StrokeOfCornersOnlyFitsExactly) {
  for (const Ring& base : {Ring{{0, 0}, {40, 0}, {40, 14}, {0, 14}}, l_ring(30, 20, 12, 8)}) {
    const Ring stroke = transformed(base, -0.37, 1.6, {-220, 310});
    const PlaceFit fit = fit_place(stroke, base, {}, "feature 4");
    EXPECT_NEAR(fit.rotation, -0.37, 1e-9);
    EXPECT_NEAR(fit.scale, 1.6, 1e-9);
    EXPECT_NEAR(fit.offset[0], -220, 1e-6);
    EXPECT_NEAR(fit.offset[1], 310, 1e-6);
    EXPECT_FALSE(fit.outline_not_found);
  }
}

// A stroke that does not trace the footprint (a thin L around a lot's corner, for a rectangular
// model): the refinement runs off, the axes' fit stands and says so.
TEST(PlaceFit, StrokeNotTracingTheOutlineKeepsTheAxesFit) {
  const Ring base{{0, 0}, {40, 0}, {40, 14}, {0, 14}};
  const Ring stroke = l_ring(100, 20, 80, 10);  // a long, thin L around the lot's corner
  const PlaceFit fit = fit_place(stroke, base, {}, "feature 5");
  PlaceOptions axes_only;
  axes_only.refine = false;
  const PlaceFit axes = fit_place(stroke, base, axes_only, "feature 5");
  EXPECT_TRUE(fit.outline_not_found);
  EXPECT_EQ(fit.rotation, axes.rotation);
  EXPECT_EQ(fit.scale, axes.scale);
  EXPECT_FALSE(axes.outline_not_found);
}

// The geodesic area and side lengths of the ring (GeographicLib's PolygonArea and Geodesic on
// WGS84) against the tangent plane's.
void expect_plane_matches_geodesics(const std::vector<LonLat>& ring) {
  const TangentPlaneRing plane = tangent_plane_ring(ring, "stroke");
  GeographicLib::PolygonArea polygon(GeographicLib::Geodesic::WGS84());
  for (const LonLat& p : ring) polygon.AddPoint(p.lat, p.lon);
  double perimeter = 0, area = 0;
  polygon.Compute(false, true, perimeter, area);
  EXPECT_NEAR(area_axes(plane.ring, "stroke").area, std::abs(area), 1e-6 * std::abs(area));
  for (size_t i = 0; i + 1 < ring.size(); ++i) {
    double s12 = 0;
    GeographicLib::Geodesic::WGS84().Inverse(ring[i].lat, ring[i].lon, ring[i + 1].lat,
                                             ring[i + 1].lon, s12);
    const Point2& a = plane.ring[i];
    const Point2& b = plane.ring[i + 1];
    EXPECT_NEAR(std::hypot(b[0] - a[0], b[1] - a[1]), s12, 1e-7 * s12);
  }
}

TEST(PlaceTangentPlane, MatchesGeodesicAreaAndLengths) {
  // A 300 m x 150 m block in Soho, London.
  const std::vector<LonLat> soho{
      {-0.1360, 51.5130}, {-0.1317, 51.5130}, {-0.1317, 51.5143}, {-0.1360, 51.5143}};
  expect_plane_matches_geodesics(soho);
  const TangentPlaneRing plane = tangent_plane_ring(soho, "stroke");
  EXPECT_NEAR(plane.origin.lon, -0.13385, 1e-12);
  EXPECT_NEAR(plane.origin.lat, 51.51365, 1e-12);
  // Across the antimeridian: one small ring, its origin on the 180th meridian.
  const std::vector<LonLat> dateline{
      {179.9996, -16.5}, {-179.9997, -16.5}, {-179.9997, -16.4996}, {179.9996, -16.4996}};
  expect_plane_matches_geodesics(dateline);
  EXPECT_NEAR(std::abs(tangent_plane_ring(dateline, "stroke").origin.lon), 179.99995, 1e-9);
}

// A stroke of lon/lat traced around an L placed by a known transform (its points put on the globe
// by geodesics from a point in Zion: azimuth and distance of their east-north offsets), fitted
// back: the rotation and scale, and where the model's origin lands on the globe.
TEST(PlaceTangentPlane, LonLatStrokeGivesTheKnownPlacement) {
  const GeographicLib::Geodesic& wgs84 = GeographicLib::Geodesic::WGS84();
  const double centre_lat = 37.2, centre_lon = -112.95;
  const auto on_globe = [&](Point2 p) {
    LonLat q;
    wgs84.Direct(centre_lat, centre_lon, std::atan2(p[0], p[1]) * 180 / kPi, std::hypot(p[0], p[1]),
                 q.lat, q.lon);
    return q;
  };
  const Ring base = l_ring(24, 16, 10, 7);
  const double rotation = 2.2, scale = 1.5;
  const Point2 offset{-35, 20};
  Uniform uniform(4);
  const Ring stroke = drawn_stroke(transformed(base, rotation, scale, offset), 400, 0, uniform);
  std::vector<LonLat> lonlat;
  for (const Point2& p : stroke) lonlat.push_back(on_globe(p));
  const TangentPlaneRing plane = tangent_plane_ring(lonlat, "stroke");
  const PlaceFit fit = fit_place(plane.ring, base, {}, "feature 9");
  EXPECT_NEAR(fit.rotation, rotation, 1e-5);
  EXPECT_NEAR(fit.scale, scale, 1e-6);
  const GeographicLib::LocalCartesian frame(plane.origin.lat, plane.origin.lon, 0);
  double lat = 0, lon = 0, height = 0;
  frame.Reverse(fit.offset[0], fit.offset[1], 0, lat, lon, height);
  const LonLat want = on_globe(offset);
  double metres = 0;
  wgs84.Inverse(lat, lon, want.lat, want.lon, metres);
  EXPECT_LT(metres, 0.01);
}

TEST(PlaceTangentPlane, PointsOffTheGlobeNameWhere) {
  EXPECT_THROW(tangent_plane_ring({}, "feature 4: stroke"), Error);
  try {
    tangent_plane_ring({{10, 45}, {10.001, 91}, {10, 45.001}}, "feature 4: stroke");
    ADD_FAILURE() << "latitude 91 was accepted";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "feature 4: stroke: point 1 (lon 10.001, lat 91) is not on the globe");
  }
}

TEST(PlaceFit, HeadingConvention) {
  EXPECT_NEAR(rotation_from_heading_deg(0), 0, 1e-15);
  EXPECT_NEAR(rotation_from_heading_deg(-90), kPi / 2, 1e-15);  // +y to the west
  EXPECT_NEAR(rotation_from_heading_deg(180), kPi, 1e-15);
  EXPECT_NEAR(rotation_from_heading_deg(270), kPi / 2, 1e-12);
}

}  // namespace
}  // namespace maquette::structures
