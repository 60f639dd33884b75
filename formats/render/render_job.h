// `maquette render panorama` as a library call: checks the layers and the camera, builds the
// terrain, rasterizes, shades and writes the panorama and its guides (render/panorama.h).
#pragma once

#include <optional>
#include <string>

#include "core/grid.h"
#include "render/camera.h"
#include "render/panorama.h"
#include "render/panorama_strips.h"
#include "render/progressive_bend.h"
#include "store/store.h"

namespace maquette {

struct PanoramaJob {
  std::string dem, texture, land_cover;  // layer names; texture and land_cover may be ""
  bool smooth_land_cover = false;        // render/panorama.h PanoramaLook::smooth_land_cover
  CameraSpec camera;                     // eye.height above the ellipsoid, or the terrain
  bool above_ground = false;             // camera.eye.height is above the terrain
  std::optional<GeodeticPoint> look_at;  // replaces camera.heading and pitch
  double exaggeration = 1;
  // The DEM's level by distance: a sample drawn at most this many pixels wide (render/
  // terrain_scene.h scene_cells); 0: every tile at full resolution.
  double sample_pixels = 1;
  // Its base is set here: the ground under the eye as the DEM gives it, not exaggerated (the
  // ellipsoid where the DEM has no data there).
  // The hillshade keeps the unbent terrain's normals, so the bend does not relight the far slopes;
  // the distance guide is the bent point's, the one drawn.
  ProgressiveBend bend;
  bool stretch = true;  // render/panorama.h PanoramaLook::stretch
  double haze_distance = 60000;
  double sun_azimuth = 315, sun_altitude = 45;
  bool shadows = false;  // the terrain's cast shadows (render/terrain_shadow.h) under that sun
  // Samples per pixel side for the colour, 1 to 8 (render/panorama_supersample.h); 1: each
  // pixel's centre.
  int antialias = 1;
  int strip_rows = 0;  // render_panorama_files: rows per strip (0: default_strip_rows)
  // render_panorama: rows of a strip of fragments (0: about 2 M pixels; draw_panorama); the same
  // picture for any.
  int fragment_rows = 0;
};

// The checks of render_panorama that need no store: the camera and --look-at places, the field of
// view, size, --antialias, --sun, --haze-distance, the bend, --strip-rows. Throws
// maquette::Error naming the option and value at fault.
void check_panorama_job(const PanoramaJob& job);

// Throws maquette::Error naming the option and value at fault: an unknown layer or one of the
// wrong kind (--dem: image/option_layers.h height_layer; --texture: uint8 of 1, 3 or 4 channels;
// --land-cover: categorical), a bend out of range (render/progressive_bend.h), a camera below the
// terrain (or
// --above-ground where the DEM has no data), a field of view, pitch or size out of range
// (render/camera.h), a --camera or --look-at not a finite lon, a lat within +-90 and a finite
// height, a --sun not finite, a sun altitude outside (0, 90) with --shadows, no tile of the DEM in
// the view (render/terrain_scene.h build_terrain_scene), an --antialias outside 1 to 8 or whose
// samples would make a picture over 65536 pixels wide or high.
Panorama render_panorama(const Store& store, const Grid& grid, PanoramaJob job);

// The same written to OUT and its guides (render/panorama_strips.h), drawn in strips of
// job.strip_rows rows: the same files as write_panorama(render_panorama(...)) whatever the strips,
// in bounded memory. Throws as render_panorama, for strip_rows < 0, and for an OUT (or its guides
// or silhouettes) that is the store.
void render_panorama_files(const Store& store, const Grid& grid, PanoramaJob job,
                           const std::string& out);

}  // namespace maquette
