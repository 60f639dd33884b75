#include "render/painting_fit_job.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <type_traits>

#include "core/error.h"
#include "core/output_file.h"
#include "image/option_layers.h"
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
  TerrainHeights dem_heights(store, grid, height_layer(store, job.dem));
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
                        const GroundWarp* ground_warp, OutputFile& file) {
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
  file.write([&] { write_new_file(file.temp_path(), text); });
}

Panorama render_warped_panorama(const Store& store, const Grid& grid, PanoramaJob render,
                                const PictureWarp& unwarp) {
  const int w = render.camera.width, h = render.camera.height;
  std::vector<PicturePoint> sources(size_t(w) * size_t(h));
  double beyond = 0;  // pixels
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const PicturePoint p = unwarp({i + 0.5, j + 0.5});
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]))
        throw Error("--panorama: the fit's warp sends pixel (" + std::to_string(i) + ", " +
                    std::to_string(j) + ") nowhere (" + number(p[0]) + ", " + number(p[1]) + ")");
      sources[size_t(j) * size_t(w) + size_t(i)] = p;
      beyond = std::max({beyond, -p[0], p[0] - w, -p[1], p[1] - h});
    }
  // None: the picture as drawn. Capped: the sources beyond it are clamped onto its edge below.
  const int most = std::max(w, h) / 2;
  const int margin = beyond > 0 ? int(std::min(std::ceil(beyond), double(most))) : 0;
  if (beyond > most)
    spdlog::warn(
        "--panorama: the fit's warp reaches {:.0f} px beyond the picture; drawn with a "
        "margin of {} px (half its larger side), the pixels beyond take its edge",
        beyond, margin);
  else
    spdlog::info("--panorama: drawn with a margin of {} px", margin);
  const double focal = PinholeCamera(render.camera).focal();
  render.camera.width = w + 2 * margin;
  render.camera.height = h + 2 * margin;
  render.camera.fov = 2 * std::atan((w * 0.5 + margin) / focal) * 180 / std::numbers::pi;
  const Panorama wide = render_panorama(store, grid, render);
  const int ww = wide.width;
  std::vector<size_t> source(sources.size());
  for (size_t k = 0; k < sources.size(); ++k) {  // clamped: a source beyond takes the edge
    const auto x = int(std::clamp(std::floor(sources[k][0]) + margin, 0.0, ww - 1.0));
    const auto y = int(std::clamp(std::floor(sources[k][1]) + margin, 0.0, wide.height - 1.0));
    source[k] = size_t(y) * size_t(ww) + size_t(x);
  }
  const auto moved = [&source](const auto& values, size_t wide_pixels) {
    const size_t channels = values.size() / wide_pixels;  // 0 for a guide not drawn
    std::remove_cvref_t<decltype(values)> out(source.size() * channels);
    for (size_t k = 0; k < source.size(); ++k)
      for (size_t c = 0; c < channels; ++c)
        out[k * channels + c] = values[source[k] * channels + c];
    return out;
  };
  const size_t n = size_t(ww) * size_t(wide.height);
  Panorama out;  // every picture and guide of Panorama (render/panorama.h) moved
  out.width = w;
  out.height = h;
  out.rgb = moved(wide.rgb, n);
  out.altitude = moved(wide.altitude, n);
  out.distance = moved(wide.distance, n);
  out.origin = wide.origin;
  out.lon_offset = moved(wide.lon_offset, n);
  out.lat_offset = moved(wide.lat_offset, n);
  out.land_cover = moved(wide.land_cover, n);
  out.cast_shadow = moved(wide.cast_shadow, n);
  out.shading = moved(wide.shading, n);
  out.silhouette = moved(wide.silhouette, n);
  return out;
}

}  // namespace maquette
