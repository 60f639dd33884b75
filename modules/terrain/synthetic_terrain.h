// A deterministic synthetic terrain for demos and tests: fractal 3D gradient noise of the
// position's unit normal, so it is seamless across tiles and faces and independent of the grid.
#pragma once

#include <cstdint>

#include "core/ecef.h"

namespace maquette::terrain {

struct TerrainParams {
  int64_t seed = 1;
  double amplitude_m = 2500;  // scale of the relief
  int octaves = 7;
  double feature_km = 400;  // wavelength of the coarsest octave
};

// Elevation in metres (>= 0: the sea is clamped to sea level) where the ellipsoid normal is `up`.
double synthetic_elevation(const Vec3& up, const TerrainParams& params);

}  // namespace maquette::terrain
