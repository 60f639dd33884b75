// A lake's fog volume straight from its depth raster (vdb/column_fog.h): one column of voxels per
// wet pixel, on the pixels' own lattice, no mesh in between.
//
// Contract: a non-empty body of `basin` (fill_basin). The raster's pixels lie in the frame on an
// affine lattice: pixel (col, row)'s centre at seed + (col - seed_col) * along_col + (row -
// seed_row) * along_row (metres; the seed is body.seed's pixel, on the water's surface: the
// lattice is the surface's tangent plane there); `surface[w]` is the place in the frame of the
// water's surface over wet pixel body.wet[w]'s centre. The columns are the wet pixels' bounding
// box, column (i, j) pixel (col0 + i, row1 - j) (j grows against the rows, so that the lattice
// keeps the frame's handedness), along the plane's normal; voxels are a pixel across and the
// greatest depth over voxels_deep high, their faces in a layer at the surface's mean height over
// the plane (the top of voxel k = -1); a wet pixel's column
// holds the voxels whose centres lie between its surface height and that minus its depth (none for
// a pixel shallower than half a voxel; voxels_deep for the deepest). Dry pixels' columns are
// empty. Made of the surface's places and the lattice alone, the volume is the same body in any
// frame (to rounding). Time and memory are linear in the bounding box's pixels; in parallel by
// chunks of wet pixels (TBB), the same bits for any thread count.
#pragma once

#include <array>
#include <span>

#include "vdb/column_fog.h"
#include "water_body.h"

namespace maquette::deform {

struct PixelLattice {
  std::array<double, 3> seed{}, along_col{}, along_row{};
};

FogColumns lake_columns(const BasinRaster& basin, const WaterBody& body,
                        const PixelLattice& lattice, std::span<const std::array<double, 3>> surface,
                        int voxels_deep);

}  // namespace maquette::deform
