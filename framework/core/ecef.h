// Earth-centred, earth-fixed (ECEF) positions of points on the WGS84 ellipsoid, and the local
// east/north/up unit vectors at a point (up is the ellipsoid normal): the metric frame in which
// operators measure true distances between pixels.
#pragma once

#include <array>

#include "core/grid.h"

namespace maquette {

using Vec3 = std::array<double, 3>;

// ECEF position (metres) of a point `height` metres above the ellipsoid.
Vec3 ecef(LonLat p, double height = 0);
Vec3 east_unit(LonLat p);
Vec3 north_unit(LonLat p);
Vec3 up_unit(LonLat p);

}  // namespace maquette
