// Fitting the renderer's camera (render/camera.h) and Terrain Bender's bend
// (render/progressive_bend.h) to a painting from control points (issue 19, paper 000's hurdle:
// painted panoramas are bent and distorted): the camera and bend under which `render panorama`
// draws each control point's ground point where the painting shows it.
//
// The model is the renderer's, exactly: a pinhole on WGS84 with no roll and the principal point at
// the painting's centre, the eye anywhere (heading, pitch, horizontal fov), and optionally the
// progressive bend about the ground under the eye (its base as render_job.h sets it). The solve:
// - the focal length, when not given, scanned over fields of view from 5 to 120 degrees (10 %
//   steps), OpenCV's solvePnP (SQPnP; the ground points in the east-north-up frame of their
//   centroid) at each, the one with the least reprojection error kept;
// - then Levenberg-Marquardt (Eigen's, numeric Jacobian) on the reprojection errors over the eye
//   (3), heading, pitch and focal length;
// - with the bend, Levenberg-Marquardt again over those and the bend's curvature and start, from
//   that plain camera and a few radii and starts scaled on the points' distance from the eye; the
//   least error kept;
// - optionally the residual warp, a thin-plate spline of the painting taking the fitted points onto
//   the clicks (render/painting_fit_warp.h).
// Deterministic (no threads, no random starts). Errors are pixels in the painting.
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <vector>

#include "core/grid.h"
#include "render/camera.h"
#include "render/painting_fit_warp.h"
#include "render/progressive_bend.h"

namespace maquette {

// A point of the painting (picture coordinates, render/camera.h) and the ground point it shows
// (height above the ellipsoid).
struct GroundClick {
  double x = 0, y = 0;
  GeodeticPoint ground;
};

struct PaintingFitOptions {
  int width = 0, height = 0;  // the painting's, pixels
  std::optional<double> fov;  // horizontal field of view, degrees; scanned when absent
  bool bend = false;          // also fit the progressive bend's radius and start
  // The ground's height above the ellipsoid at a point (the DEM's, 0 where it has none, as
  // render_job.h does): the bend's base is the ground under the eye.
  std::function<double(LonLat)> ground_height;
  // When set, the residual warp (render/painting_fit_warp.h) is fitted with this smoothing to what
  // the camera and bend leave of the clicks' errors.
  std::optional<double> warp_smoothing;
};

struct PaintingFit {
  CameraSpec camera;     // width and height: the painting's
  ProgressiveBend bend;  // infinite radius when not fitted; its base set
  PictureWarp warp;      // the identity unless PaintingFitOptions::warp_smoothing is set
  // Its inverse, approximately: the spline with the same smoothing taking the clicks back onto the
  // fitted points (a painting pixel to the pixel the camera and bend draw there).
  PictureWarp unwarp;
  double rms_error = 0;  // pixels, over the clicks, of the camera and bend (before the warp)
  std::vector<PicturePoint> fitted;   // where the camera and bend put each click's ground point
  std::vector<GeodeticPoint> ground;  // the clicks' ground points, in their order

  // Where the fit puts ground points in the painting: the camera's and bend's pixel moved by the
  // warp; NaN behind the eye.
  std::vector<PicturePoint> to_painting(const std::vector<GeodeticPoint>& ground) const;
};

// Throws maquette::Error when fewer clicks are given than half the unknowns plus one, or than 4
// (5 unknowns, +1 without a fov, +2 with the bend: 4 clicks, 5 with the bend), the fov is out of
// (0, 170], or the camera found leaves a click behind the eye.
PaintingFit fit_painting(const std::vector<GroundClick>& clicks, const PaintingFitOptions& options);

// Where `camera` and `bend` (render/progressive_bend.h, its base set) draw `ground` points (picture
// coordinates); NaN for a point behind the eye. Precondition: PinholeCamera(camera) is valid.
std::vector<PicturePoint> project_ground(const CameraSpec& camera, const ProgressiveBend& bend,
                                         const std::vector<GeodeticPoint>& ground);

}  // namespace maquette
