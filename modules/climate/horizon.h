// Horizon angles of the pixels of a tile: the highest elevation angle of the terrain (bilinear
// samples of the DEM and its halo, lowered by the earth's curvature d^2 / 2R) along evenly spaced
// azimuths, up to a maximum distance, the edge of the halo or the first sample without data.
// Samples are one pixel apart up to kFineSteps pixels, then ever sparser (the spacing doubles
// every time the distance does) and read the DEM's maxima over squares reaching halfway to the
// neighbouring samples (dilated_dem.h): a far peak subtends a small angle, and is found anyway.
// Computed for square blocks of pixels at once: the pixels of a block march along the same
// steps (those of the block's centre pixel's frame), so every step reads the same offsets for the
// whole block and the inner loop runs along contiguous samples (vectorized).
#pragma once

#include <vector>

#include "dilated_dem.h"
#include "local_frame.h"

namespace maquette::climate {

class HorizonAngles {
 public:
  static constexpr int kBlock = 32;      // pixels along a block's side (tiles are >= 64)
  static constexpr int kFineSteps = 16;  // samples one pixel apart
  static constexpr int kLevels = 5;      // of maxima: the spacing grows up to 2^kLevels pixels

  // `directions` azimuths 0, 360/directions, ... degrees.
  HorizonAngles(int directions, double max_distance_m);

  int directions() const { return directions_; }

  // The angles (radians; -pi/2 where nothing is found) of the kBlock x kBlock pixels from
  // (col0, row0) of the DEM (`surfaces`, of kLevels levels), marching with `frame`'s steps:
  // out[(row * kBlock + col) * directions + k] for the block's pixel (col, row) and azimuth k
  // (sun.h's Horizon::angles). `zmax` is the highest sample of the DEM (halo included): a march
  // ends once no farther sample could rise above the horizon found (the bound
  // (zmax - z0 - d^2 / 2R) / d only falls with d).
  // Directions whose flag in `used` is 0 are skipped (left at -pi/2).
  void compute(const DilatedDem& surfaces, float zmax, const std::vector<char>& used,
               const PixelFrame& frame, int col0, int row0, std::vector<float>& out) const;

 private:
  int directions_;
  double max_distance_;
};

}  // namespace maquette::climate
