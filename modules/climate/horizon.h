// Horizon angles of a pixel: the highest elevation angle of the terrain (bilinear samples of the
// DEM and its halo, lowered by the earth's curvature d^2 / 2R) along evenly spaced azimuths, up
// to a maximum distance or the edge of the halo.
#pragma once

#include <vector>

#include "local_frame.h"

namespace maquette::climate {

class HorizonAngles {
 public:
  // `directions` azimuths 0, 360/directions, ... degrees.
  HorizonAngles(int directions, double max_distance_m);

  // Fills `out` (size directions) for pixel (col, row) of `dem` at elevation z0 (radians; -pi/2
  // where nothing is found).
  void compute(const Tile<float>& dem, const PixelFrame& frame, int col, int row, double z0,
               std::vector<double>& out) const;

  // Horizon towards `azimuth` (radians clockwise from north), linear between directions.
  double at(const std::vector<double>& angles, double azimuth) const;

 private:
  int directions_;
  double max_distance_;
};

}  // namespace maquette::climate
