// Where a region mosaic's samples lie: their lon/lat, their metres east and north in the tangent
// plane of a reference point (GeographicLib's LocalCartesian on WGS84), and the way back from a
// lon/lat to fractional sample coordinates of the mosaic (sample centres at integers). Strokes
// are measured in metres there, and the height field's cotangent weights see the true shape of
// rHEALPix's pixels (equal-area, not square away from the face centres).
#pragma once

#include <GeographicLib/LocalCartesian.hpp>
#include <array>
#include <optional>

#include "core/grid.h"

namespace maquette::deform {

using EastNorth2 = std::array<double, 2>;

class MosaicFrame {
 public:
  // The mosaic's face, its pixel level and the global face pixel of its sample (0, 0).
  MosaicFrame(const Grid& grid, int face, int pixel_level, int64_t origin_col, int64_t origin_row,
              LonLat reference);

  EastNorth2 local(LonLat p) const;
  LonLat lonlat(EastNorth2 p) const;
  LonLat sample_lonlat(int col, int row) const;  // the centre of mosaic sample (col, row)
  // Fractional mosaic sample coordinates (col, row) of `p`; nullopt when it lies on another face.
  std::optional<std::array<double, 2>> sample(LonLat p) const;

 private:
  const Grid& grid_;
  int face_, pixel_level_;
  int64_t origin_col_, origin_row_;
  PlaneSquare face_square_;
  GeographicLib::LocalCartesian tangent_plane_;
};

}  // namespace maquette::deform
