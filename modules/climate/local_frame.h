// The local metric frame of each pixel of a tile with a halo, from the tile's true geometry
// (core/tile_frame.h): latitude, the east/north metres of one column and one row step (central
// differences of the neighbours' positions), and from them the DEM gradient and straight-line
// marches along an azimuth. terrain.derive fits Horn's 3x3 plane instead; climate only needs
// the central-difference gradient.
#pragma once

#include <vector>

#include "core/grid.h"
#include "core/tile.h"
#include "core/tile_bilinear.h"  // bilinear(), the frame's sampling
#include "core/tile_frame.h"

namespace maquette::climate {

// Metres east and north of one step along a tile axis, in the pixel's tangent plane.
using Step = EastNorth;

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

constexpr double kEarthRadius = 6371008.8;  // mean radius, for the curvature drop d^2 / 2R

}  // namespace maquette::climate
