// Where a region mosaic's samples lie: their lon/lat, their metres east and north in the tangent
// plane of a reference point (core/enu_frame.h, at the ellipsoid), and the way back from a
// lon/lat to fractional sample coordinates of the mosaic (sample centres at integers). Strokes
// are measured in metres there, and the height field's cotangent weights see the true shape of
// rHEALPix's pixels (equal-area, not square away from the face centres).
//
// Across face seams the mosaic is the plane unfolded around its face (core/unfolded_faces.h, as
// the runner pastes it): a sample beyond the face's edge is the neighbour face's pixel laid
// there, and a lon/lat on a neighbour face maps to its place in that plane.
#pragma once

#include <array>
#include <optional>

#include "core/enu_frame.h"
#include "core/grid.h"
#include "core/unfolded_faces.h"

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
  // Fractional mosaic sample coordinates (col, row) of `p`; nullopt when its face has no place in
  // the unfolded plane (the face opposite the mosaic's).
  std::optional<std::array<double, 2>> sample(LonLat p) const;

 private:
  const Grid& grid_;
  UnfoldedFaces plane_;
  int64_t origin_col_, origin_row_;
  EnuFrame tangent_plane_;
};

}  // namespace maquette::deform
