// Feature strokes (../shared/DESIGN.md, "Strokes"; paper 002 §3.1): the features of tool
// "feature" of a features port, parsed and checked. A stroke is a control curve (a LineString of
// lon/lat; its Z values, when present, are the elevation along it, else the `profile` attribute
// [[distance_m, z]...] gives it, else it is draped on the DEM) and a cross section `cross_section`
// [[offset_m, dz_m]...]: dz (vertical, metres) relative to the control curve at a horizontal
// offset across it, negative offsets on the left; its extent is the field of influence.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/grid.h"
#include "runtime/vector_feature.h"

namespace maquette::deform {

// A piecewise-linear function given by (x, y) knots with strictly increasing x.
using Knots = std::vector<std::array<double, 2>>;

// y at x, linear between knots; x outside the knots takes the nearest end's y.
double piecewise_linear(const Knots& knots, double x);

struct FeatureStroke {
  int64_t id = 0;
  std::vector<LonLat> curve;  // the control curve, at least two distinct points
  std::vector<double> z;      // the curve's Z per point; empty when it has none
  Knots profile;              // [distance_m, z]; empty when absent
  Knots cross_section;        // [offset_m, dz_m], at least two knots, offsets increasing
};

// How close (m, horizontally) a control curve may come to itself: closer counts as touching.
inline constexpr double kSelfContactM = 0.01;
// A cross section spanning offset 0 must have dz 0 there, within this (m): the control curve's
// elevation holds at the curve, and a section disagreeing with it would fight it.
inline constexpr double kCurveDzToleranceM = 1e-6;

// "lon X, lat Y" to 8 significant digits, for messages naming where a stroke is at fault.
std::string lonlat_text(LonLat p);

// The strokes of tool "feature" among `features` (other tools are left to other operators), in
// the order given. Throws maquette::Error naming `port`, the feature id and the field at fault: a
// geometry other than a LineString, fewer than two distinct points, a control curve that crosses
// or touches itself (non-consecutive segments within kSelfContactM, collinear overlaps included)
// or turns back over its previous segment, a missing or malformed cross_section or profile (not
// [[number, number]...] of finite numbers with strictly increasing first members, fewer than two
// pairs), a cross section whose dz at offset 0 (within its offsets) is not 0, or both Z values
// and a profile.
std::vector<FeatureStroke> feature_strokes(const FeatureList& features, const std::string& port);

}  // namespace maquette::deform
