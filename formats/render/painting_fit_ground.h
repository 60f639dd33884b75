// The residual warp of a painting fit taken to the ground (issue 19: "the remaining error warped
// away by deforming the DEM"): a horizontal displacement field d, east and north metres in the
// fitted eye's east-north-up frame, such that the DEM moved by it, h'(x) = h(x - d(x)), drawn under
// the fitted camera and bend puts each clicked feature where the painting shows it.
//
// At each click, d is the move of its ground point G (its height kept) onto the ray of the fitted
// camera and bend through the pixel the picture warp (render/painting_fit_warp.h) sends G's fitted
// pixel to: the click itself with no smoothing, the click less its noise when smoothed. So the
// smoothing lives in the picture, where the clicks' noise is, and the ground spline interpolates.
// Between the clicks, a thin-plate spline of those moves (the same spline, in metres, its scale
// the moved points' extent); away from them it fades to nothing: in full within R_i of click i
// (R_i the distance to its nearest other click), none beyond 2 R_i from every click (a smoothstep
// between), so a DEM far from the clicks is left as it is, bit for bit. R_i is at least two of the
// DEM's samples: clicks closer than that (a bridge's two ends) still move the four samples whose
// bilinear blend draws each of them, so the feature moves (a reach below a sample moved none).
#pragma once

#include <vector>

#include "core/enu_frame.h"
#include "core/grid.h"
#include "render/painting_fit.h"

namespace maquette {

class GroundWarp {
 public:
  // Throws maquette::Error naming
  // the click (its index) whose ground point no horizontal move puts on its pixel (a ray that
  // misses the height of the point, behind the eye or at the horizon), and the spline's errors
  // (clicks whose moved points are collinear). `dem_sample_m`: the DEM's sample spacing (metres,
  // > 0). Precondition: fit.warp was fitted (it may be the identity when the clicks fit exactly).
  GroundWarp(const PaintingFit& fit, double dem_sample_m);

  // The point whose height the moved DEM takes at `p` (p - d(p)); `p` itself, the same bits,
  // where the warp has faded out.
  LonLat source(LonLat p) const;
  // True when the warp leaves every point within `radius` metres of `p` where it is.
  bool still_near(LonLat p, double radius) const;

  // Per click, its ground point's move (east, north metres) and R_i (metres).
  const std::vector<PicturePoint>& moves() const { return moves_; }
  const std::vector<double>& reach() const { return reach_; }

 private:
  // How much of the spline's move is taken at (east, north): 1 near the clicks, 0 far.
  double weight(double east, double north) const;

  EnuFrame eye_;
  PictureWarp spline_;                 // from the moved points back to the ground points
  std::vector<PicturePoint> centres_;  // the moved points, east and north
  std::vector<PicturePoint> moves_;    // the moves
  std::vector<double> reach_;          // R_i
};

}  // namespace maquette
