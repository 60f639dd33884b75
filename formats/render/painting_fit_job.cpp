#include "render/painting_fit_job.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/error.h"
#include "core/output_file.h"
#include "render/terrain_scene.h"

namespace maquette {
namespace {

std::string number(double v) {
  std::ostringstream s;
  s.precision(12);
  s << v;
  return s.str();
}

}  // namespace

PaintingFit fit_painting_to_store(const Store& store, const Grid& grid, const PaintingFitJob& job,
                                  const PaintingPoints& points, const std::string& points_path) {
  const auto dem = store.layer(job.dem);
  if (!dem || dem->kind != LayerKind::Raster || dem->channels != 1)
    throw Error("--dem layer '" + job.dem + "' is not a one-channel raster layer of the store " +
                store.path());
  TerrainHeights dem_heights(store, grid, *dem);
  std::vector<GroundClick> clicks;
  for (const ControlPoint& p : points.points) {
    GroundClick c{p.x, p.y, {p.lon, p.lat, 0}};
    if (p.height) {
      c.ground.height = *p.height;
    } else {
      const auto h = dem_heights({p.lon, p.lat});
      if (!h)
        throw Error(points_path + ": " + p.name + " has no height and the --dem layer '" + job.dem +
                    "' has no data at lon " + number(p.lon) + ", lat " + number(p.lat));
      c.ground.height = *h;
    }
    clicks.push_back(c);
  }
  PaintingFitOptions options;
  options.width = points.width;
  options.height = points.height;
  options.fov = job.fov;
  options.bend = job.bend;
  options.warp_smoothing = job.warp_smoothing;
  options.ground_height = [&](LonLat at) { return dem_heights(at).value_or(0); };
  return fit_painting(clicks, options);
}

void write_painting_fit(const PaintingFit& fit, const PaintingPoints& points,
                        const GroundWarp* ground_warp, const std::string& path) {
  using nlohmann::json;
  const CameraSpec& c = fit.camera;
  json out;
  out["camera"] = {{"eye", {c.eye.lon, c.eye.lat, c.eye.height}},
                   {"heading", c.heading},
                   {"pitch", c.pitch},
                   {"fov", c.fov},
                   {"size", {c.width, c.height}}};
  std::string options = "--camera " + number(c.eye.lon) + " " + number(c.eye.lat) + " " +
                        number(c.eye.height) + " --heading " + number(c.heading) + " --pitch " +
                        number(c.pitch) + " --fov " + number(c.fov) + " --size " +
                        std::to_string(c.width) + " " + std::to_string(c.height);
  if (fit.bend.bends()) {
    out["bend"] = {{"radius", fit.bend.radius}, {"start", fit.bend.start}};
    options +=
        " --bend-radius " + number(fit.bend.radius) + " --bend-start " + number(fit.bend.start);
  } else {
    out["bend"] = nullptr;
  }
  out["render_options"] = options;
  out["rms_error"] = fit.rms_error;
  json clicks = json::array();
  for (size_t i = 0; i < points.points.size(); ++i) {
    const ControlPoint& p = points.points[i];
    const auto& f = fit.fitted[i];
    clicks.push_back({{"name", p.name},
                      {"x", p.x},
                      {"y", p.y},
                      {"fitted_x", f[0]},
                      {"fitted_y", f[1]},
                      {"error", std::hypot(f[0] - p.x, f[1] - p.y)}});
    if (ground_warp) clicks.back()["ground_move"] = ground_warp->moves()[i];
  }
  out["points"] = clicks;
  if (fit.warp.centres().empty()) {
    out["warp"] = nullptr;
  } else {
    out["warp"] = {{"scale", fit.warp.scale()},
                   {"centres", fit.warp.centres()},
                   {"weights", fit.warp.weights()},
                   {"affine", fit.warp.affine()}};
  }
  const std::string text = out.dump(2) + '\n';
  write_file_whole(path, text);  // whole or not at all: an older file stays as it was
}

Panorama warp_panorama(const Panorama& panorama, const PictureWarp& unwarp) {
  const int w = panorama.width, h = panorama.height;
  std::vector<size_t> source(size_t(w) * size_t(h));
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const PicturePoint p = unwarp({i + 0.5, j + 0.5});
      const int x = std::clamp(int(std::floor(p[0])), 0, w - 1);
      const int y = std::clamp(int(std::floor(p[1])), 0, h - 1);
      source[size_t(j) * size_t(w) + size_t(i)] = size_t(y) * size_t(w) + size_t(x);
    }
  const auto moved = [&source](const auto& values) {
    auto out = values;
    const size_t channels = values.size() / source.size();  // 0 for a guide not drawn
    for (size_t k = 0; k < source.size(); ++k)
      for (size_t c = 0; c < channels; ++c)
        out[k * channels + c] = values[source[k] * channels + c];
    return out;
  };
  Panorama out = panorama;
  out.rgb = moved(panorama.rgb);
  out.altitude = moved(panorama.altitude);
  out.distance = moved(panorama.distance);
  out.lon = moved(panorama.lon);
  out.lat = moved(panorama.lat);
  out.land_cover = moved(panorama.land_cover);
  out.cast_shadow = moved(panorama.cast_shadow);
  out.silhouette = moved(panorama.silhouette);
  return out;
}

}  // namespace maquette
