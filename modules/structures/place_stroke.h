// structures.place's fit (README.md "The fit"; paper 002 §7.4, after Severn, Samavati and Sousa,
// "Transformation strokes", SBM 2006): the similarity transform that puts an object's base
// footprint into a closed stroke drawn around it on the terrain, from the principal axes of the
// two polygons' AREAS (second moments of the region, not of the vertices: a stroke's vertices
// crowd where it was drawn slowly, its area does not care).
//
// Both polygons are in a plane, metres: the base in the model's frame (x, y horizontal), the
// stroke in the east-north tangent plane (the operator projects its lon/lat there). A model point
// p goes to  scale * R(rotation) * p + offset  in the stroke's plane.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "content/content.h"
#include "core/grid.h"

namespace maquette::structures {

using Point2 = std::array<double, 2>;
// A simple polygon's ring, either orientation, closed implicitly (a repeated last point is fine).
using Ring = std::vector<Point2>;

// The principal axes of a polygon's area, with what decides the half-turn of the major axis.
struct AreaAxes {
  double area = 0;       // > 0
  Point2 centroid{};     // the area centroid
  double major_var = 0;  // area variance along the major axis (integral of u^2 dA / area), m^2
  double minor_var = 0;  // the same along the minor axis, <= major_var
  double angle = 0;      // the major axis's angle from +x, counter-clockwise, in (-pi/2, pi/2]
  // Dimensionless third moments of the area along the major axis u and the minor axis v, the
  // latter v = u turned a quarter counter-clockwise: integral of u^3 dA / (area * major_var^1.5).
  double skew_major = 0, skew_minor = 0;
};

// The area axes of `ring`. Throws maquette::Error prefixed with `where` when the ring has fewer
// than three points, a non-finite coordinate or no area (precondition: it does not cross itself;
// a figure-eight's lobes cancel).
AreaAxes area_axes(const Ring& ring, const std::string& where);

// The refinement matches the stroke with its edges cut into pieces no longer than the stroke's
// major standard deviation / kRefineDensity (for a rectangle, its long side / 28).
inline constexpr double kRefineDensity = 8;

struct PlaceOptions {
  // Smallest major_var / minor_var (of the stroke, and of the base) for the axes to give a
  // heading. A square or disc stroke of 32 points with 2 % noise reaches 1.07 (2,000 trials in
  // tests/place_stroke_test.cpp), a footprint of aspect 1.3 is at 1.69 and the moments' heading
  // error grows as 1 / (ratio - 1): 1.25 sits between, with margin on both sides.
  double min_axis_ratio = 1.25;
  // Smallest |skew . skew'| (base's and stroke's skewness vectors) that decides the half-turn;
  // below it the fit keeps the axes' rotation nearer zero and says so
  // (PlaceFit::half_turn_decided). Measured with 2 % stroke noise: a stroke's skewness from noise
  // alone is 0.009 on average (0.06 at most), so a symmetric base whose own vertices are off by
  // as much stays below 0.003; the L-shapes of the tests (base skewness >= 0.11) give >= 0.011.
  double min_skew_product = 0.005;
  // Refine the axes' transform by matching the base's outline to the stroke (ICP, point to
  // line, on the stroke's points and its long edges cut by kRefineDensity): with 64 points of 2 %
  // noise the moments alone err up to 3.1 degrees at aspect 1.3, the refined fit 1.2 (README.md
  // gives both distributions).
  bool refine = true;
  // An explicit rotation (radians, counter-clockwise from the model's +x to east) overrides the
  // axes: then a stroke of nearly equal axes is no error.
  std::optional<double> rotation;
};

struct PlaceFit {
  double rotation = 0;  // radians, counter-clockwise, in (-pi, pi]
  double scale = 1;     // uniform; sqrt(stroke area / base area) before the refinement
  Point2 offset{};      // where the model's origin goes: stroke centroid - scale R base centroid
  bool half_turn_decided = true;   // false: the skewness could not tell rotation from rotation + pi
  double axis_ratio = 0;           // the stroke's major_var / minor_var
  bool outline_not_found = false;  // the refinement left the axes' fit far behind: not used
};

// The transform that puts `base` (model metres) into `stroke` (tangent-plane metres): the area
// centroids coincide, the major axes align (the half-turn chosen so the skewness vectors agree),
// the areas match; then, unless options.refine is off or options.rotation is given (a heading set
// by hand may not fit the outline), the similarity minimising the squared distances of the
// stroke's points to the placed base outline, started there (precondition: the stroke traces the
// footprint's outline, as it does around a building in the orthophoto; a refinement that changes
// the scale by more than 25 % or moves the model by more than the stroke's major standard
// deviation has not found the outline, and the axes' fit is returned, outline_not_found set).
// Throws maquette::Error naming `feature` (e.g. "structures.place: feature 12") for a degenerate
// ring (area_axes) or, without options.rotation, when the stroke's axes are nearly equal (axis
// ratio < options.min_axis_ratio) or the base's are (its heading is then undefined too).
PlaceFit fit_place(const Ring& stroke, const Ring& base, const PlaceOptions& options,
                   const std::string& feature);

// A stroke of lon/lat in its tangent plane, where fit_place takes it.
struct TangentPlaneRing {
  EnuOrigin origin;  // the east-north-up frame at the mean of the points, on the ellipsoid
  Ring ring;         // the points' east and north (metres) in that frame
};

// Projects `ring` orthogonally on the tangent plane of the ellipsoid at the mean of its points
// (core/enu_frame.h; across 1 km the plane departs from the ellipsoid by 8 cm
// vertically and shortens distances by less than 1e-8). Longitudes are unwrapped from the first
// point's, so a ring across the antimeridian stays whole. Throws maquette::Error prefixed with
// `where` for an empty ring or a point off the globe (non-finite, |lat| > 90).
TangentPlaneRing tangent_plane_ring(const std::vector<LonLat>& ring, const std::string& where);

// The rotation of fit_place for a heading in degrees clockwise from north of the model's +y axis
// (the convention of glTF viewers' "heading" and of OSM's `direction`).
double rotation_from_heading_deg(double heading_deg);

}  // namespace maquette::structures
