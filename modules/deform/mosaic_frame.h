// Where a region mosaic's samples lie: their lon/lat, their metres east and north in the tangent
// plane of a reference point (core/enu_frame.h, at the ellipsoid), and the way back from a
// lon/lat to fractional sample coordinates of the mosaic (core/mosaic_geometry.h: sample centres
// at integers, across face seams through the plane unfolded around the mosaic's face). Strokes
// are measured in metres there, and the height field's cotangent weights see the true shape of
// rHEALPix's pixels (equal-area, not square away from the face centres).
#pragma once

#include <array>
#include <optional>

#include "core/enu_frame.h"
#include "core/grid.h"
#include "core/mosaic_geometry.h"

namespace maquette::deform {

using EastNorth2 = std::array<double, 2>;

class MosaicFrame {
 public:
  // The mosaic's face, its pixel level and the global face pixel of its sample (0, 0).
  MosaicFrame(const Grid& grid, int face, int pixel_level, int64_t origin_col, int64_t origin_row,
              LonLat reference);

  EastNorth2 local(LonLat p) const;
  LonLat lonlat(EastNorth2 p) const;
  // The centre of mosaic sample (col, row); throws maquette::Error naming the sample when it lies
  // in a gap of the unfolded plane (beyond a face corner) or beyond one face width.
  LonLat sample_lonlat(int col, int row) const;
  // The same, nullopt for a sample in a gap of the plane or beyond one face width.
  std::optional<LonLat> sample_centre(int col, int row) const;
  // Fractional mosaic sample coordinates (col, row) of `p`; nullopt when its face has no place in
  // the unfolded plane (the face opposite the mosaic's).
  std::optional<std::array<double, 2>> sample(LonLat p) const;
  // The same of the tangent plane's point p (on the ellipsoid below it), NaN where it has none.
  std::array<double, 2> local_sample(EastNorth2 p) const;
  // The face pixel of sample (0, 0) in the plane unfolded around the mosaic's face: sample(p)
  // plus it is the same for every mosaic of that plane (a tiling-independent frame).
  std::array<double, 2> origin() const { return origin_; }

 private:
  MosaicGeometry samples_;
  std::array<double, 2> origin_;
  EnuFrame tangent_plane_;
};

}  // namespace maquette::deform
