// The local metric frame of each pixel of a tile with a halo, computed from the true pixel
// positions (core/halo.h pixel_source + pixel_centre, so turned halo pixels from another face
// sit where they really are): latitude, the east/north metres of one column and one row step,
// and from them the DEM gradient and straight-line marches along an azimuth.
//
// This is the climate module's own minimal version of what terrain.derive does (central
// differences instead of Horn's 3x3 fit; terrain's geometry code lives in the terrain module,
// which modules cannot share).
#pragma once

#include <array>
#include <vector>

#include "core/grid.h"
#include "core/tile.h"

namespace maquette::climate {

// Metres east and north of one step along a tile axis, in the pixel's tangent plane.
struct Step {
  double east = 0, north = 0;
};

struct PixelFrame {
  double lat = 0;      // degrees
  Step col, row;       // one column step (+col), one row step (+row)
  bool valid = false;  // false when a neighbour has no position (beyond one face width)
};

// DEM gradient in the tangent plane: metres of rise per metre east and north.
struct Gradient {
  double east = 0, north = 0;
};

class LocalFrames {
 public:
  LocalFrames(const Grid& grid, CellId cell, int size);

  const PixelFrame& at(int col, int row) const { return frames_[size_t(row) * size_ + col]; }

  // Gradient of `dem` (halo >= 1) at interior pixel (col, row); false on NaN or no frame.
  bool gradient(const Tile<float>& dem, int col, int row, Gradient& out) const;

 private:
  int size_;
  std::vector<PixelFrame> frames_;  // interior pixels only
};

// A straight march from a pixel along an azimuth (degrees clockwise from north), in fractional
// pixel steps of at most one pixel along either axis.
struct March {
  double dcol = 0, drow = 0;  // pixels per step
  double metres = 0;          // horizontal metres per step
};
March march(const PixelFrame& frame, double azimuth_deg);

// Bilinear sample of channel 0 at fractional pixel (x, y); NaN outside the tile and its halo or
// where a corner is NaN.
double bilinear(const Tile<float>& tile, double x, double y);

constexpr double kEarthRadius = 6371008.8;  // mean radius, for the curvature drop d^2 / 2R

}  // namespace maquette::climate
