// maquette render fit: the camera and progressive bend of a painting from control points (painting
// pixel <-> ground point) against a DEM layer, written as JSON, and optionally the panorama of the
// store under that camera with its guides: the painting's altitude and land-cover masks
// (formats/render/painting_fit_job.h); with --warped-dem, the DEM warped so that the fitted camera
// draws the clicked features where the painting shows them, as a new layer
// (formats/render/painting_fit_dem.h).
#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <optional>
#include <vector>

#include "cli/commands.h"
#include "core/enu_frame.h"
#include "core/output_clash.h"
#include "core/output_file.h"
#include "render/painting_fit_dem.h"
#include "render/painting_fit_job.h"
#include "render/render_job.h"

namespace maquette::cli {
namespace {

struct FitOptions {
  std::string store, points, out, panorama, texture, land_cover;
  std::optional<std::string> warped_dem;
  PaintingFitJob job;
  PanoramaJob render;  // with --panorama: its look (haze, sun, shadows)
};

// Clicks the fit puts farther than 2 % of the painting's diagonal from where they were clicked: a
// pixel paired with the wrong place, a mirrored painting (244 px rms on Zion's clicks), were told
// only as the rms error.
void warn_far_clicks(const PaintingFit& fit, const PaintingPoints& points,
                     const std::string& path) {
  const double limit = 0.02 * std::hypot(points.width, points.height);
  std::string far;
  int count = 0;
  for (size_t i = 0; i < points.points.size(); ++i) {
    const ControlPoint& p = points.points[i];
    const double error = std::hypot(fit.fitted[i][0] - p.x, fit.fitted[i][1] - p.y);
    if (!(error > limit)) continue;
    if (++count <= 3)
      far += fmt::format("{}{} by {:.1f} px", far.empty() ? "" : ", ", p.name, error);
  }
  if (count > 0)
    spdlog::warn(
        "{}: {} of {} clicks land farther than {:.1f} px (2 % of the painting's diagonal) from "
        "where they were clicked ({}{}): is each click's pixel paired with the place it shows?",
        path, count, points.points.size(), limit, far, count > 3 ? ", ..." : "");
}

// Control points whose places lie nearly on one line of the map (six clicks along one valley
// fitted at 0.19 px, silently) leave the camera's turn about that line to their heights alone: a
// fit that matches them may be far from the painter's eye. The line: the points' principal axis
// on the ground (east, north about their centroid); "nearly": their spread across it under 5 % of
// their spread along it.
void warn_clicks_on_a_line(const PaintingFit& fit, const std::string& path) {
  const EnuFrame frame(fit.ground.front());
  double ex = 0, ny = 0;
  std::vector<std::array<double, 3>> places;
  for (const GeodeticPoint& g : fit.ground) {
    places.push_back(frame.to_enu(g.lon, g.lat));
    ex += places.back()[0];
    ny += places.back()[1];
  }
  ex /= double(places.size());
  ny /= double(places.size());
  double xx = 0, yy = 0, xy = 0;
  for (const auto& p : places) {
    xx += (p[0] - ex) * (p[0] - ex);
    yy += (p[1] - ny) * (p[1] - ny);
    xy += (p[0] - ex) * (p[1] - ny);
  }
  // The 2 x 2 covariance's eigenvalues, in closed form.
  const double mean = (xx + yy) / 2, half_gap = std::hypot((xx - yy) / 2, xy);
  const double along = std::sqrt((mean + half_gap) / double(places.size()));
  const double across = std::sqrt(std::max(0.0, mean - half_gap) / double(places.size()));
  if (along > 0 && across < 0.05 * along)
    spdlog::warn(
        "{}: the {} control points lie nearly on one line of the map ({:.0f} m across it, {:.0f} "
        "m along it, standard deviations): the camera's turn about that line rests on their "
        "heights alone, so the fit may match them from the wrong place; add points away from it",
        path, places.size(), across, along);
}

void run(const FitOptions& o) {
  const PaintingFitJob& job = o.job;
  std::vector<std::string> outputs = {o.out};
  if (!o.panorama.empty()) {
    for (const std::string& file : panorama_files(o.panorama)) outputs.push_back(file);
    check_outputs_distinct({{"OUT", outputs[0]},
                            {"--panorama", outputs[1]},
                            {"--panorama's guides", outputs[2]},
                            {"--panorama's silhouettes", outputs[3]}});
  }
  check_outputs_spare_inputs(outputs, {{"the store", o.store}, {"the control points", o.points}});
  if (!o.panorama.empty()) panorama_picture_format(o.panorama);  // before the fit, not after it
  const auto store =
      Store::open(o.store, o.warped_dem ? Store::Mode::ReadWrite : Store::Mode::ReadOnly);
  if (o.warped_dem) check_warped_dem_name(*store, *o.warped_dem);
  const PaintingPoints points = read_painting_points(o.points);
  const PaintingFit fit = fit_painting_to_store(*store, default_grid(), job, points, o.points);
  // The ground warp is found before anything is written: a click it cannot move leaves no files.
  std::optional<GroundWarp> ground_warp;
  if (o.warped_dem) {
    const LayerInfo dem = *store->layer(job.dem);
    ground_warp.emplace(fit, default_grid().level_info(dem.level, dem.tile_size).pixel_m);
  }
  // The panorama is rendered before anything is written: bad --texture or --land-cover layers
  // leave no files.
  std::optional<Panorama> panorama;
  if (!o.panorama.empty()) {
    PanoramaJob render = o.render;
    render.dem = job.dem;
    render.texture = o.texture;
    render.land_cover = o.land_cover;
    render.camera = fit.camera;
    render.bend = fit.bend;
    panorama = render_warped_panorama(*store, default_grid(), render, fit.unwarp);
  }
  // The files before the layer: a file that cannot be written leaves no new layer behind, which
  // would make every re-run refuse its name. The fit is put in place after the panorama's files
  // are: one that cannot be written leaves no fit.
  OutputFile fit_file(o.out);
  write_painting_fit(fit, points, ground_warp ? &*ground_warp : nullptr, fit_file);
  if (panorama) write_panorama(*panorama, o.panorama);
  fit_file.commit();
  spdlog::info("wrote {}: rms error {:.2f} px over {} points", o.out, fit.rms_error,
               points.points.size());
  if (panorama) spdlog::info("wrote {} and its guides", o.panorama);
  warn_far_clicks(fit, points, o.points);
  warn_clicks_on_a_line(fit, o.points);
  if (ground_warp) {
    write_warped_dem(*store, default_grid(), *store->layer(job.dem), *ground_warp, *o.warped_dem,
                     {{"command", "render fit"}, {"dem", job.dem}, {"points", o.points}});
    spdlog::info("wrote layer {}: {} moved by the fit's warp", *o.warped_dem, job.dem);
  }
}

}  // namespace

void add_render_fit_command(CLI::App* render) {
  auto o = std::make_shared<FitOptions>();
  CLI::App* cmd = render->add_subcommand(
      "fit",
      "The camera and progressive bend of a painting from control points (a JSON file of painting "
      "pixels and lon/lat[/height]) against a DEM, as JSON; with --panorama, the store drawn under "
      "that camera and its guides (the painting's altitude and land-cover masks)");
  cmd->add_option("STORE", o->store, "Store file")->required();
  cmd->add_option("POINTS", o->points,
                  "Control points: {\"width\", \"height\", \"points\": [{\"x\", \"y\", \"lon\", "
                  "\"lat\"[, \"height\" above the ellipsoid][, \"name\"]}]}")
      ->required();
  cmd->add_option("OUT", o->out, "Output JSON: camera, bend, errors, warp")->required();
  cmd->add_option("--dem", o->job.dem, "DEM layer (one-channel heights in metres)")->required();
  cmd->add_option("--fov", o->job.fov,
                  "The painting's horizontal field of view, degrees (default: fitted)")
      ->check(CLI::Range(0.0, 170.0));
  cmd->add_flag("--bend", o->job.bend, "Also fit Terrain Bender's bend radius and start");
  cmd->add_option("--warp-smoothing", o->job.warp_smoothing,
                  "Also fit the residual warp, a thin-plate spline with this smoothing (>= 0; "
                  "0.001 follows clicks with 2 px of noise)")
      ->check(CLI::Validator(
          [](std::string& text) {  // CLI::NonNegativeNumber's message printed DBL_MAX's 309 digits
            char* end = nullptr;
            const double v = std::strtod(text.c_str(), &end);
            return end != text.c_str() && *end == 0 && v >= 0
                       ? std::string()
                       : "expected a number >= 0, got " + text;
          },
          "NUMBER >= 0"));
  cmd->add_option(
         "--warped-dem", o->warped_dem,
         "Also write the --dem layer warped by the fit's warp (taken to the ground) as this "
         "new layer: drawn under the fitted camera and bend, its clicked features lie "
         "where the painting shows them")
      ->needs("--warp-smoothing");
  cmd->add_option("--panorama", o->panorama,
                  "Also render the store under the fitted camera and bend, moved by the warp onto "
                  "the painting, to this PNG, with its guides, as `render panorama` does");
  cmd->add_option("--texture", o->texture, "With --panorama: imagery layer");
  cmd->add_option("--land-cover", o->land_cover, "With --panorama: categorical layer guide");
  add_panorama_look_options(cmd, o->render);
  cmd->callback([o] { run(*o); });
}

}  // namespace maquette::cli
