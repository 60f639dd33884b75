// `maquette render fit` as a library call: a painting's control points (painting_fit_points.h)
// fitted against a store's DEM (painting_fit.h), the result written as JSON.
#pragma once

#include <optional>
#include <string>

#include "core/grid.h"
#include "core/output_file.h"
#include "render/painting_fit.h"
#include "render/painting_fit_ground.h"
#include "render/painting_fit_points.h"
#include "render/panorama.h"
#include "render/render_job.h"
#include "store/store.h"

namespace maquette {

struct PaintingFitJob {
  std::string dem;            // layer name: one-channel heights (metres)
  std::optional<double> fov;  // degrees; scanned when absent
  bool bend = false;
  std::optional<double> warp_smoothing;  // no warp when absent
};

// The points without a height get the DEM's (converted to the ellipsoid through its vertical
// datum, bilinear); the bend's base is the DEM's height under the eye (0 where it has none), as
// `render panorama` sets it, so the camera and bend found draw the clicks' ground points where the
// painting shows them. Throws maquette::Error naming the option, file, point or value at fault:
// --dem not a one-channel raster layer of the store, a point without a height where the DEM has no
// data, and fit_painting's errors.
PaintingFit fit_painting_to_store(const Store& store, const Grid& grid, const PaintingFitJob& job,
                                  const PaintingPoints& points, const std::string& points_path);

// The fit as JSON: "camera" ("eye": lon, lat, height above the ellipsoid; heading, pitch, fov;
// "size": width, height), "bend" (radius and start in metres; null without the bend), "rms_error"
// (pixels, before the warp), "render_options" (the same camera and bend as `render panorama`
// options), "points" (each click's name, x, y and where the camera and bend put it: fitted_x,
// fitted_y, error; with `ground_warp`, ground_move: its ground point's move, east and north metres
// in the eye's frame), and "warp" (painting_fit_warp.h: scale, centres, weights, affine; null
// without the warp), into `file`'s temporary name (the caller commits it, with the files written
// beside it). Throws maquette::Error naming the file when it cannot be written.
void write_painting_fit(const PaintingFit& fit, const PaintingPoints& points,
                        const GroundWarp* ground_warp, OutputFile& file);

// The panorama `render` draws (its camera and bend a fit's) moved by the fit's warp onto the
// painting: each pixel takes the picture and guides of the pixel `unwarp` (PaintingFit::unwarp)
// sends its centre to (nearest). Where that lies beyond the picture, the view is drawn wider: with
// a margin as wide as the farthest such pixel, at the same focal length and centre, so every pixel
// shows what the camera sees there. The margin is at most half the picture's larger side (the
// spline extrapolates linearly past the clicks: bunched clicks may send a corner thousands of
// pixels out); a pixel sent beyond it takes the wide view's nearest edge pixel. Throws
// maquette::Error naming the pixel that `unwarp` sends to no finite place, and as
// render_panorama.
Panorama render_warped_panorama(const Store& store, const Grid& grid, PanoramaJob render,
                                const PictureWarp& unwarp);

}  // namespace maquette
