#include "render/render_job.h"

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <memory>

#include "core/error.h"
#include "core/output_clash.h"
#include "gdal/vertical_datum.h"
#include "image/layer_sampler.h"
#include "image/option_layers.h"
#include "render/rasterizer.h"
#include "render/terrain_scene.h"
#include "render/terrain_shadow.h"

namespace maquette {
namespace {

std::string metres(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f m", v);
  return text;
}

// A point given as --camera or --look-at: lon and lat swapped, or a NaN, were told as an invalid
// grid point or a pitch out of range.
void check_place(const std::string& option, const GeodeticPoint& p) {
  if (!std::isfinite(p.lon) || !(std::abs(p.lat) <= 90) || !std::isfinite(p.height))
    throw Error(option + " " + fmt::format("{} {} {}", p.lon, p.lat, p.height) +
                ": expected LON LAT HEIGHT, a finite longitude, a latitude within +-90 degrees "
                "and a finite height");
}

}  // namespace

void check_panorama_job(const PanoramaJob& job) {
  check_place("--camera", job.camera.eye);
  if (job.look_at) check_place("--look-at", *job.look_at);
  if (!std::isfinite(job.sun_azimuth) || !std::isfinite(job.sun_altitude))
    throw Error("--sun " + fmt::format("{} {}", job.sun_azimuth, job.sun_altitude) +
                " must be finite");
  if (!(job.haze_distance > 0))
    throw Error("--haze-distance " + std::to_string(job.haze_distance) + " must be positive");
  check_bend(job.bend);
  if (job.antialias < 1 || job.antialias > 8)
    throw Error("--antialias " + std::to_string(job.antialias) +
                " must be 1 to 8 (samples per pixel side)");
  const int64_t side = std::max(job.camera.width, job.camera.height);
  if (side > 65536)
    throw Error("--size " + std::to_string(job.camera.width) + " " +
                std::to_string(job.camera.height) + ": a picture is at most 65536 pixels a side");
  if (side * job.antialias > 65536)
    throw Error("--antialias " + std::to_string(job.antialias) + " on a picture of " +
                std::to_string(job.camera.width) + " x " + std::to_string(job.camera.height) +
                " pixels: its samples would span more than 65536 pixels; lower it");
  if (job.shadows && !(job.sun_altitude > 0 && job.sun_altitude < 90))
    throw Error("--sun altitude " + std::to_string(job.sun_altitude) +
                " must be in (0, 90) degrees for --shadows");
  if (job.strip_rows < 0)
    throw Error("--strip-rows " + std::to_string(job.strip_rows) + " must be 0 or more");
  check_camera_spec(job.camera);
  // heading and pitch as given: a --look-at replaces them later
}

namespace {

// What render_panorama and render_panorama_files share: the checked layers, the camera, the bent
// terrain and the look (whose layer pointers point into this).
struct PreparedPanorama {
  std::optional<LayerInfo> texture, land_cover;
  std::optional<PinholeCamera> camera;
  TerrainScene scene;
  std::vector<uint8_t> shadow;  // per vertex, with --shadows (render/terrain_shadow.h)
  PanoramaLook look;
};

std::unique_ptr<PreparedPanorama> prepare(const Store& store, const Grid& grid, PanoramaJob job) {
  auto prepared = std::make_unique<PreparedPanorama>();
  std::optional<LayerInfo>& texture = prepared->texture;
  std::optional<LayerInfo>& land_cover = prepared->land_cover;
  const LayerInfo dem = height_layer(store, job.dem);
  if (!job.texture.empty()) {
    texture = option_raster_layer(store, "--texture", job.texture);
    if (texture->dtype != DType::U8 || texture->channels == 2 || texture->channels > 4)
      throw Error("--texture layer '" + job.texture + "' is " +
                  std::string(dtype_name(texture->dtype)) + " with " +
                  std::to_string(texture->channels) +
                  " channels: expected uint8 imagery of 1, 3 or 4 channels");
    if (texture->semantics == Semantics::Categorical)
      throw Error("--texture layer '" + job.texture +
                  "' is categorical (classes, not colours): give it as --land-cover");
  }
  if (!job.land_cover.empty()) {
    land_cover = option_raster_layer(store, "--land-cover", job.land_cover);
    if (land_cover->semantics != Semantics::Categorical)
      throw Error("--land-cover layer '" + job.land_cover + "' is not categorical");
  }

  check_panorama_job(job);
  GeodeticPoint& eye = job.camera.eye;
  const LonLat at{eye.lon, eye.lat};
  // The DEM's conversion to the ellipsoid, set up once for the eye's ground and the mesh.
  const auto datum = std::make_shared<const EllipsoidalHeights>(ellipsoidal_heights(dem));
  // The ground as drawn (exaggerated): the eye's height above it, the check and the bend's base
  // (the DEM's tiles read for it freed before the mesh is made).
  const auto ground = TerrainHeights(store, grid, dem, job.exaggeration, datum)(at);
  if (job.above_ground) {
    if (!(eye.height > 0))  // 0 or below: an eye in the ground, a picture of its inside
      throw Error("--above-ground: the camera's height " + metres(eye.height) +
                  " must be above the ground (more than 0 m)");
    if (!ground)
      throw Error("--above-ground: the --dem layer '" + dem.name +
                  "' has no data under the camera at lon " + std::to_string(eye.lon) + ", lat " +
                  std::to_string(eye.lat));
    eye.height += *ground;
  } else if (ground && eye.height <= *ground) {
    throw Error("the camera (" + metres(eye.height) +
                " above the ellipsoid) is below the terrain there (" + metres(*ground) +
                "): raise its height or give it --above-ground");
  }
  if (job.look_at) {
    const auto [heading, pitch] = aim(eye, *job.look_at);
    job.camera.heading = heading;
    job.camera.pitch = pitch;
  }
  const PinholeCamera& camera = prepared->camera.emplace(job.camera);
  // Tiles out of view are left out unless the vertices move afterwards (a bend) or shadows are
  // cast: terrain beside or behind the picture throws shadows into it.
  // The DEM's tiles decoded once for the mesh and the shadows (kept for those only when cast).
  const auto dem_tiles =
      job.shadows ? LayerSampler::shared_tiles(store, grid, dem, dem.level) : nullptr;
  TerrainScene& scene = prepared->scene =
      build_terrain_scene(store, grid, dem, camera, job.exaggeration, job.sample_pixels,
                          !job.bend.bends() && !job.shadows, datum, dem_tiles);
  if (job.shadows)  // on the unbent terrain: the bend is a drawing device, not the sun's
    prepared->shadow = shadow_vertices(dem_tiles, grid, dem, scene, camera, job.exaggeration,
                                       job.sun_azimuth, job.sun_altitude);
  job.bend.base = ground.value_or(0) - eye.height;  // the ENU up of the ground under the eye
  bend_positions(scene.mesh.positions, job.bend);
  std::map<int, int> tiles;  // per level
  for (const CellId c : scene.cells) ++tiles[c.level()];
  std::string levels;
  for (const auto& [level, count] : tiles)
    levels +=
        (levels.empty() ? "" : ", ") + std::to_string(count) + " at level " + std::to_string(level);
  spdlog::debug("panorama: tiles {}; {} vertices, {} triangles", levels, scene.slot.size(),
                scene.mesh.triangle_count());
  PanoramaLook& look = prepared->look;
  look.texture = texture ? &*texture : nullptr;
  look.land_cover = land_cover ? &*land_cover : nullptr;
  look.smooth_land_cover = job.smooth_land_cover;
  look.haze_distance = job.haze_distance;
  look.stretch = job.stretch;
  look.sun_azimuth = job.sun_azimuth;
  look.sun_altitude = job.sun_altitude;
  look.shadow = job.shadows ? &prepared->shadow : nullptr;
  look.antialias = job.antialias;
  return prepared;
}

}  // namespace

Panorama render_panorama(const Store& store, const Grid& grid, PanoramaJob job) {
  const int fragment_rows = job.fragment_rows;
  const auto p = prepare(store, grid, std::move(job));
  return draw_panorama(store, grid, p->scene, *p->camera, p->look, fragment_rows);
}

void render_panorama_files(const Store& store, const Grid& grid, PanoramaJob job,
                           const std::string& out) {
  check_outputs_spare_inputs(panorama_files(out), {{"the store", store.path()}});
  panorama_picture_format(out);  // a wrong extension or a missing directory said before drawing
  const int rows = job.strip_rows > 0 ? job.strip_rows : default_strip_rows(job.camera.width);
  const auto p = prepare(store, grid, std::move(job));
  render_strips(store, grid, p->scene, *p->camera, p->look, rows, out);
}

}  // namespace maquette
