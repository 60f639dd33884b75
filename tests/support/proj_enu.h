// The oracle of east-north-up coordinates: PROJ's pipeline geodetic -> geocentric (cart) ->
// topocentric at an origin on WGS84, independently of the program's core/enu_frame.h
// (GeographicLib).
#pragma once

#include <array>

#include "core/grid.h"

struct PJconsts;

namespace maquette::test {

class ProjEnu {
 public:
  // The frame at (lon, lat) degrees, `height` metres above the ellipsoid; fails the test (gtest)
  // when PROJ refuses it.
  ProjEnu(double lon, double lat, double height);
  ~ProjEnu();
  ProjEnu(const ProjEnu&) = delete;
  ProjEnu& operator=(const ProjEnu&) = delete;
  // The point at (lon, lat) degrees, `height` metres above the ellipsoid, in the frame (metres).
  std::array<double, 3> operator()(LonLat p, double height) const;

 private:
  PJconsts* pj_ = nullptr;
};

}  // namespace maquette::test
