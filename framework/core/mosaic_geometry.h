// Where a region mosaic's samples lie on the ellipsoid, and back: the one mapping between a
// mosaic's sample coordinates and lon/lat (runtime/operator.h Mosaic: `face` and `pixel_level`,
// sample (0, 0) at face pixel (origin_col, origin_row)).
//
// Convention: sample centres at integers. Sample (col, row) is face pixel (origin_col + col,
// origin_row + row), whose centre is core/halo.h pixel_centre (the pixel's square from its
// corner (col, row) to (col + 1, row + 1) in the face's pixel frame, its centre at + 0.5).
//
// Across face seams the mosaic is the plane unfolded around `face` (core/unfolded_faces.h, as the
// runner pastes a step that spans faces): a sample beyond the face's edge is the neighbour face's
// pixel laid there, and a lon/lat on a neighbour face maps to its place in that plane. A mosaic
// within its face (the runner's default) is the special case where every sample is on `face`.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "core/grid.h"
#include "core/unfolded_faces.h"

namespace maquette {

class MosaicGeometry {
 public:
  // Throws maquette::Error for a pixel level outside 0..60 (core/unfolded_faces.h).
  MosaicGeometry(const Grid& grid, int face, int pixel_level, int64_t origin_col,
                 int64_t origin_row);

  // The centre of sample (col, row); nullopt when it lies in a gap of the unfolded plane (beyond
  // a face corner) or beyond one face width.
  std::optional<LonLat> sample_lonlat(int64_t col, int64_t row) const;
  // Fractional sample coordinates (col, row) of `p`; nullopt when its face has no place in the
  // unfolded plane (the face opposite the mosaic's).
  std::optional<std::array<double, 2>> sample(LonLat p) const;

  int face() const { return plane_.anchor(); }

 private:
  const Grid& grid_;
  UnfoldedFaces plane_;
  int64_t origin_col_, origin_row_;
};

}  // namespace maquette
