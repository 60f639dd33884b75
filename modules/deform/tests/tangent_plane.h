// A site's tangent plane for the tests, independent of the code under test: GeographicLib's
// LocalCartesian on WGS84, lon/lat <-> metres east and north, points put on the ellipsoid (about
// d^2 / 2R below the plane at horizontal distance d).
#pragma once

#include <GeographicLib/LocalCartesian.hpp>
#include <array>

#include "core/grid.h"

namespace maquette::deform {

struct TangentPlane {
  explicit TangentPlane(LonLat site) : plane(site.lat, site.lon, 0) {}

  LonLat lonlat(double e, double n) const {
    double lat = 0, lon = 0, h = 0;
    plane.Reverse(e, n, -(e * e + n * n) / 12742017.6, lat, lon, h);
    return {lon, lat};
  }
  std::array<double, 2> local(LonLat p) const {
    double e = 0, n = 0, u = 0;
    plane.Forward(p.lat, p.lon, 0, e, n, u);
    return {e, n};
  }

  GeographicLib::LocalCartesian plane;
};

}  // namespace maquette::deform
