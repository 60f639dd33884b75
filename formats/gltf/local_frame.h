// The local east-north-up frame of an export: every mesh of an export is placed in one frame
// (so vertices shared by neighbouring cells, also across face seams, get identical coordinates),
// measured from an offset at the mesh, its node's translation (gltf/lattice.h), with glTF's y-up
// axes (x east, y up, z south); 3D Tiles turns y-up content to z-up, then the root tile's
// transform (enu_to_ecef) places the frame on the globe.
#pragma once

#include <array>

#include "core/ecef.h"
#include "core/grid.h"

namespace maquette {

class LocalFrame {
 public:
  explicit LocalFrame(LonLat origin);

  LonLat origin() const { return origin_; }
  // glTF coordinates (x east, y up, z south) of a geodetic point (height above the ellipsoid).
  Vec3 to_gltf(LonLat p, double height) const;
  // Column-major 4x4 ENU -> ECEF (metres), for a 3D Tiles tile transform.
  std::array<double, 16> enu_to_ecef() const;

 private:
  LonLat origin_;
  Vec3 origin_ecef_;
  std::array<Vec3, 3> axes_;  // east, north, up in ECEF
};

}  // namespace maquette
