#include "render/render_job.h"

#include <spdlog/spdlog.h>

#include <cstdio>

#include "core/error.h"
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

LayerInfo raster_layer(const Store& store, const std::string& option, const std::string& name) {
  const auto info = store.layer(name);
  if (!info) throw Error(option + " layer '" + name + "' is not in the store " + store.path());
  if (info->kind != LayerKind::Raster)
    throw Error(option + " layer '" + name + "' is a " + std::string(layer_kind_name(info->kind)) +
                " layer: expected a raster");
  return *info;
}

}  // namespace

Panorama render_panorama(const Store& store, const Grid& grid, PanoramaJob job) {
  const LayerInfo dem = raster_layer(store, "--dem", job.dem);
  if (dem.channels != 1)
    throw Error("--dem layer '" + dem.name + "' has " + std::to_string(dem.channels) +
                " channels: expected one channel of heights");
  std::optional<LayerInfo> texture, land_cover;
  if (!job.texture.empty()) {
    texture = raster_layer(store, "--texture", job.texture);
    if (texture->dtype != DType::U8 || texture->channels == 2 || texture->channels > 4)
      throw Error("--texture layer '" + job.texture + "' is " +
                  std::string(dtype_name(texture->dtype)) + " with " +
                  std::to_string(texture->channels) +
                  " channels: expected uint8 imagery of 1, 3 or 4 channels");
  }
  if (!job.land_cover.empty()) {
    land_cover = raster_layer(store, "--land-cover", job.land_cover);
    if (land_cover->semantics != Semantics::Categorical)
      throw Error("--land-cover layer '" + job.land_cover + "' is not categorical");
  }

  if (!(job.haze_distance > 0))
    throw Error("--haze-distance " + std::to_string(job.haze_distance) + " must be positive");
  check_bend(job.bend);
  if (job.shadows && !(job.sun_altitude > 0 && job.sun_altitude < 90))
    throw Error("--sun altitude " + std::to_string(job.sun_altitude) +
                " must be in (0, 90) degrees for --shadows");
  GeodeticPoint& eye = job.camera.eye;
  const LonLat at{eye.lon, eye.lat};
  const auto ground = terrain_ellipsoidal_height(store, grid, dem, at);
  if (job.above_ground) {
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
  const PinholeCamera camera(job.camera);
  TerrainScene scene = build_terrain_scene(store, grid, dem, camera, job.exaggeration);
  std::vector<uint8_t> shadow;
  if (job.shadows)  // on the unbent terrain: the bend is a drawing device, not the sun's
    shadow = shadow_vertices(store, grid, dem, scene, camera, job.exaggeration, job.sun_azimuth,
                             job.sun_altitude);
  job.bend.base = ground.value_or(0) - eye.height;  // the ENU up of the ground under the eye
  bend_positions(scene.mesh.positions, job.bend);
  spdlog::debug("panorama: {} vertices, {} triangles", scene.altitude.size(),
                scene.mesh.triangle_count());
  const Fragments fragments = rasterize(scene.mesh, camera);
  PanoramaLook look;
  look.texture = texture ? &*texture : nullptr;
  look.land_cover = land_cover ? &*land_cover : nullptr;
  look.haze_distance = job.haze_distance;
  look.stretch = job.stretch;
  look.sun_azimuth = job.sun_azimuth;
  look.sun_altitude = job.sun_altitude;
  look.shadow = job.shadows ? &shadow : nullptr;
  return shade_panorama(store, grid, scene, fragments, camera, look);
}

}  // namespace maquette
