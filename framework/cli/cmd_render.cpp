// maquette render panorama: an oblique picture of the store's terrain from a camera, with its
// guides (altitude, distance, lon/lat, land cover, silhouettes) beside it (formats/render).
#include <spdlog/spdlog.h>
#include <tbb/global_control.h>

#include <memory>

#include "cli/commands.h"
#include "render/render_job.h"

namespace maquette::cli {
namespace {

struct PanoramaOptions {
  std::string store, out;
  PanoramaJob job;
  std::vector<double> camera, look_at;
  std::vector<int> size{1600, 900};
  int threads = 0;
};

void run(const PanoramaOptions& o) {
  PanoramaJob job = o.job;
  job.camera.eye = {o.camera[0], o.camera[1], o.camera[2]};
  if (!o.look_at.empty()) job.look_at = GeodeticPoint{o.look_at[0], o.look_at[1], o.look_at[2]};
  job.camera.width = o.size[0];
  job.camera.height = o.size[1];
  const size_t threads =
      o.threads > 0
          ? size_t(o.threads)
          : tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism);
  tbb::global_control parallelism(tbb::global_control::max_allowed_parallelism, threads);
  const auto store = Store::open(o.store, Store::Mode::ReadOnly);
  render_panorama_files(*store, default_grid(), job, o.out);
  spdlog::info("wrote {} and its guides", o.out);
}

}  // namespace

void add_panorama_look_options(CLI::App* cmd, PanoramaJob& job) {
  cmd->add_option("--haze-distance", job.haze_distance,
                  "Metres at which the haze hides 63 % of the terrain's colour")
      ->capture_default_str();
  cmd->add_option_function<std::vector<double>>(
         "--sun",
         [&job](const std::vector<double>& sun) {
           job.sun_azimuth = sun[0];
           job.sun_altitude = sun[1];
         },
         "The hillshading's sun: AZIMUTH ALTITUDE, degrees")
      ->expected(2)
      ->default_str(std::to_string(int(job.sun_azimuth)) + " " +
                    std::to_string(int(job.sun_altitude)));
  cmd->add_flag("--shadows", job.shadows,
                "Cast shadows of the terrain under --sun (darkened, and a cast_shadow guide)");
  cmd->add_flag("--smooth-land-cover", job.smooth_land_cover,
                "The land_cover guide's class boundaries drawn as smooth curves through the "
                "cells' staircase (each pixel the class weighing most under a quadratic B-spline "
                "over the 3 x 3 cells around it), as a painter would draw them: for the transfer "
                "of a painting into the picture (maquette-paint); default: the cell's class")
      ->needs("--land-cover");
}

void add_render_command(CLI::App& app) {
  CLI::App* render = app.add_subcommand("render", "Draw pictures of the store's terrain");
  render->require_subcommand(1);
  auto o = std::make_shared<PanoramaOptions>();
  CLI::App* cmd = render->add_subcommand(
      "panorama",
      "An oblique picture of the terrain from a camera (CPU, deterministic), and its guides: "
      "OUT stem + -guides.tif (altitude, distance, lon, lat[, land_cover][, cast_shadow with "
      "--shadows], shading; float64, NaN on the sky), -silhouettes.png");
  cmd->add_option("STORE", o->store, "Store file")->required();
  cmd->add_option("OUT", o->out, "Output picture: .png, or .jpg / .jpeg (JPEG quality 90)")
      ->required();
  cmd->add_option("--dem", o->job.dem, "DEM layer (one-channel heights in metres)")->required();
  cmd->add_option("--texture", o->job.texture,
                  "Imagery layer draped on the terrain (uint8, 1, 3 or 4 channels; read from its "
                  "overviews where a pixel spans more than a texel; default: a plain earth "
                  "colour)");
  cmd->add_flag(
      "--no-stretch", [o](int64_t) { o->job.stretch = false; },
      "The texture's values as stored (default: stretched like `export png`, 2-98 % per band of "
      "the texels seen)");
  cmd->add_option("--land-cover", o->job.land_cover,
                  "Categorical layer written as the land_cover guide");
  cmd->add_option("--camera", o->camera,
                  "The eye: LON LAT HEIGHT (degrees; metres above the ellipsoid, or above the "
                  "terrain with --above-ground)")
      ->expected(3)
      ->required();
  cmd->add_flag("--above-ground", o->job.above_ground,
                "The camera's height is above the terrain under it");
  auto* heading =
      cmd->add_option("--heading", o->job.camera.heading, "Degrees clockwise from north")
          ->capture_default_str();
  auto* pitch = cmd->add_option("--pitch", o->job.camera.pitch,
                                "Degrees above the horizontal (negative looks down)")
                    ->capture_default_str();
  cmd->add_option("--look-at", o->look_at,
                  "Aim at LON LAT HEIGHT (metres above the ellipsoid) instead of --heading and "
                  "--pitch")
      ->expected(3)
      ->excludes(heading)
      ->excludes(pitch);
  cmd->add_option("--fov", o->job.camera.fov, "Horizontal field of view, degrees (0, 170]")
      ->capture_default_str();
  cmd->add_option("--size", o->size, "Picture WIDTH HEIGHT in pixels")
      ->expected(2)
      ->capture_default_str();
  cmd->add_option("--exaggeration", o->job.exaggeration, "Vertical exaggeration")
      ->capture_default_str();
  cmd->add_option("--sample-pixels", o->job.sample_pixels,
                  "The DEM's level by distance: far tiles from coarser levels whose samples are "
                  "at most this many pixels wide on the picture (0: every tile at full "
                  "resolution)")
      ->capture_default_str();
  CLI::Option* bend_radius = cmd->add_option(
      "--bend-radius", o->job.bend.radius,
      "Terrain Bender's progressive bending: the ground beyond --bend-start curves up "
      "on a circle of this radius, metres (default: none)");
  cmd->add_option("--bend-start", o->job.bend.start,
                  "Horizontal distance from the eye where the bending starts, metres (with "
                  "--bend-radius)")
      ->capture_default_str()
      ->needs(bend_radius);
  add_panorama_look_options(cmd, o->job);
  cmd->add_option(
         "--antialias", o->job.antialias,
         "K, samples per pixel side (1 to 8): each pixel's colour the mean of K x K samples "
         "over it (smooth skylines and ridges; K^2 samples drawn and shaded a pixel: a 4 MP "
         "picture ~3 times as long with K 2); the guides "
         "stay the pixel centre's, and gain a last band, coverage: the share of the pixel's "
         "samples that see terrain (maquette-paint anti-aliases its skyline with it)")
      ->capture_default_str();
  cmd->add_option("--strip-rows", o->job.strip_rows,
                  "Draw and write the picture in strips of this many rows, for big pictures in "
                  "bounded memory (the same files whatever the strips; 0: strips of up to 16 M "
                  "pixels)")
      ->capture_default_str();
  add_threads_option(cmd, o->threads);
  cmd->callback([o] { run(*o); });
  add_render_fit_command(render);
}

}  // namespace maquette::cli
