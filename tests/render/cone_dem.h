// The synthetic cone of the shadow and silhouette tests: a right circular cone on a plain, its
// axis on UTM zone 12's central meridian (grid north is true north there), heights above the
// ellipsoid, written as a GeoTIFF in UTM 12.
#pragma once

#include <array>
#include <functional>
#include <string>

namespace maquette::test {

constexpr double kConeLon = -111, kConeLat = 37.3;
constexpr double kConeRadius = 3000, kConeHeight = 1500, kConeBase = 1000;  // metres

// The cone's axis in UTM 12 (easting, northing).
std::array<double, 2> cone_axis();

// The cone's height above the ellipsoid at (e, n) metres east and north of its axis.
double cone_height(double e, double n);

// Writes `path`: a Float32 DEM in UTM 12 of `cells` x `cells` of `cell` metres centred on the
// cone's axis, heights `height(e, n)` (metres from the axis). Returns `path`.
std::string write_utm_dem(const std::string& path, int cells, double cell,
                          const std::function<double(double, double)>& height);

}  // namespace maquette::test
