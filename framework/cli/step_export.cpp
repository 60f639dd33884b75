// The `export` pipeline step: `maquette export FORMAT` as a task. Params mirror the command's
// options ("out" relative to the pipeline file; its directory is created); each format takes only
// its own options.
#include <filesystem>
#include <map>
#include <set>

#include "cli/builtin_steps.h"
#include "cli/export_jobs.h"
#include "core/error.h"
#include "core/json_file.h"
#include "render/render_job.h"
#include "runtime/task_operator.h"

namespace maquette::cli {
namespace {

using json = nlohmann::json;

// The options of each format; those starting with '*' are required.
const std::map<std::string, std::vector<std::string>>& format_options() {
  static const std::vector<std::string> terrain = {
      "*dem", "decimation", "position_bits", "texcoord_bits", "normal_bits", "max_mib", "force"};
  static const std::map<std::string, std::vector<std::string>> options = [] {
    std::map<std::string, std::vector<std::string>> o = {
        {"gtiff", {"*layer", "bbox", "cells", "level", "crs", "resolution", "max_mib", "force"}},
        {"png",
         {"*layer", "bbox", "cells", "ramp", "range", "bands", "hillshade", "max_size",
          "projection", "legend", "overlay"}},
        {"geojson", {"*layer", "bbox", "cells"}},
        {"gpkg", {"*layer", "bbox", "cells"}},
        {"tiles3d", {"texture", "stretch", "draco", "bbox", "cells", "content", "levels"}},
        {"glb", {"texture", "stretch", "draco", "*cells", "content", "dem"}},
        {"drc", {"*cells"}},
        {"panorama",
         {"*dem",       "texture",       "stretch",      "land_cover",    "smooth_land_cover",
          "*camera",    "above_ground",  "heading",      "pitch",         "look_at",
          "fov",        "size",          "exaggeration", "sample_pixels", "bend_radius",
          "bend_start", "haze_distance", "sun",          "shadows",       "antialias",
          "strip_rows"}}};
    for (const char* f : {"tiles3d", "glb", "drc"})
      for (const std::string& option : terrain)
        if (!(f == std::string("glb") && option == "*dem")) o[f].push_back(option);
    return o;
  }();
  return options;
}

json typed(const char* type, const std::string& description) {
  return {{"type", type}, {"description", description}};
}

OperatorSpec export_spec() {
  OperatorSpec s;
  s.name = "export";
  s.description =
      "Write layers out of the store, as `maquette export FORMAT`: GeoTIFF, PNG quicklook, "
      "GeoJSON or GeoPackage features, 3D Tiles, GLB or Draco terrain, or a panorama (as "
      "`maquette render panorama`)";
  s.kind = OperatorKind::Task;
  json formats = json::array();
  for (const auto& [format, options] : format_options()) formats.push_back(format);
  s.params_schema = {
      {"type", "object"},
      {"additionalProperties", false},
      {"required", {"format", "out"}},
      {"properties",
       {{"format", {{"type", "string"}, {"enum", formats}}},
        {"out", typed("string", "output file (tiles3d, drc: directory), relative to the pipeline")},
        {"layer", typed("string", "gtiff, png, geojson, gpkg: the layer")},
        {"bbox", array_schema("number", "only tiles overlapping this lon/lat box: W S E N")},
        {"cells",
         array_schema("string", "only tiles in these cells (glb, drc: the cells written)")},
        {"level", {{"type", "integer"}, {"minimum", 0}, {"maximum", CellId::kMaxLevel}}},
        {"crs", typed("string", "gtiff: rhealpix or EPSG:NNNN")},
        {"resolution", typed("number", "gtiff: pixel size in crs units")},
        {"ramp",
         {{"type", "string"},
          {"enum", {"grey", "viridis", "diverging", "terrain", "slope", "hypsometric"}}}},
        {"projection", {{"type", "string"}, {"enum", {"auto", "lonlat", "polar"}}}},
        {"legend", typed("boolean", "png: a legend below the picture (default true)")},
        {"overlay", typed("string", "png: a features layer drawn over the picture")},
        {"range", array_schema("number", "png: values drawn as the ramp's ends")},
        {"bands", {{"type", "array"}, {"items", {{"type", "integer"}, {"minimum", 1}}}}},
        {"hillshade", typed("boolean", "png: multiply by a hillshade")},
        {"max_size", {{"type", "integer"}, {"minimum", 16}, {"maximum", 65536}}},
        {"dem", typed("string", "tiles3d, glb, drc, panorama: the DEM layer")},
        {"texture", typed("string", "tiles3d, glb, panorama: the imagery layer")},
        {"decimation", {{"type", "integer"}, {"minimum", 1}}},
        {"position_bits", {{"type", "integer"}, {"minimum", 1}, {"maximum", 30}}},
        {"texcoord_bits", {{"type", "integer"}, {"minimum", 1}, {"maximum", 30}}},
        {"normal_bits", {{"type", "integer"}, {"minimum", 1}, {"maximum", 30}}},
        {"max_mib", {{"type", "integer"}, {"minimum", 1}}},
        {"force", typed("boolean", "above max_mib; tiles3d: into a non-empty output")},
        {"draco", typed("boolean", "false: plain GLB")},
        {"stretch", typed("boolean", "false: the texture as stored, not stretched 2-98 %")},
        {"content", array_schema("string", "tiles3d, glb: 3D content layers")},
        {"levels", typed("string", "tiles3d: cell levels A..B")},
        {"land_cover", typed("string", "panorama: categorical layer written as a guide")},
        {"smooth_land_cover",
         typed("boolean", "panorama: the land_cover guide's boundaries smoothed, not staircased")},
        {"camera", array_schema("number", "panorama: the eye, LON LAT HEIGHT")},
        {"above_ground", typed("boolean", "panorama: the camera's height is above the terrain")},
        {"heading", typed("number", "panorama: degrees clockwise from north")},
        {"pitch", typed("number", "panorama: degrees above the horizontal")},
        {"look_at", array_schema("number", "panorama: aim at LON LAT HEIGHT")},
        {"fov", typed("number", "panorama: horizontal field of view, degrees")},
        {"size", {{"type", "array"}, {"items", {{"type", "integer"}, {"minimum", 1}}}}},
        {"exaggeration", typed("number", "panorama: vertical exaggeration")},
        {"sample_pixels", typed("number", "panorama: DEM samples at most this wide, pixels")},
        {"bend_radius", typed("number", "panorama: progressive bending's radius, metres")},
        {"bend_start", typed("number", "panorama: where the bending starts, metres")},
        {"haze_distance", typed("number", "panorama: metres where haze hides 63 %")},
        {"sun", array_schema("number", "panorama: hillshading's sun, AZIMUTH ALTITUDE")},
        {"shadows", typed("boolean", "panorama: the terrain's cast shadows under the sun")},
        {"antialias",
         {{"type", "integer"},
          {"minimum", 1},
          {"maximum", 8},
          {"description", "panorama: samples per pixel side for the colour"}}},
        {"strip_rows", {{"type", "integer"}, {"minimum", 0}}}}}};
  return s;
}

// Each field given must be an option of the format, and the format's required ones given.
void check_format_options(const json& p) {
  const std::string format = p.at("format");
  const std::vector<std::string>& options = format_options().at(format);
  std::set<std::string> allowed = {"format", "out"};
  std::string list;
  for (const std::string& o : options) {
    const std::string name = o[0] == '*' ? o.substr(1) : o;
    allowed.insert(name);
    list += (list.empty() ? "" : ", ") + name;
    if (o[0] == '*' && !p.contains(name))
      throw Error("params: format " + format + " needs \"" + name + "\"");
  }
  for (const auto& [key, _] : p.items())
    if (!allowed.count(key))
      throw Error("params." + key + ": not an option of format " + format + " (it takes: " + list +
                  ")");
  for (const auto& [key, count] : {std::pair<const char*, size_t>{"range", 2},
                                   {"camera", 3},
                                   {"look_at", 3},
                                   {"size", 2},
                                   {"sun", 2}})
    if (p.contains(key) && p.at(key).size() != count)
      throw Error("params." + std::string(key) + ": expected " + std::to_string(count) +
                  " numbers, got " + excerpt(p.at(key)));
  if (p.contains("look_at") && (p.contains("heading") || p.contains("pitch")))
    throw Error("params: give \"look_at\" or \"heading\" and \"pitch\", not both");
  if (p.contains("bbox") && p.contains("cells"))
    throw Error("params: give at most one of \"bbox\" and \"cells\"");
  if (p.contains("cells"))
    for (size_t i = 0; i < p.at("cells").size(); ++i) {
      try {
        CellId::Parse(p.at("cells")[i].get<std::string>());
      } catch (const Error& e) {
        throw Error("params.cells[" + std::to_string(i) + "]: " + e.what());
      }
    }
}

RegionOptions region_of(const json& p) {
  RegionOptions r;
  read_param(p, "bbox", r.bbox);
  read_param(p, "cells", r.cells);
  return r;
}

TerrainSettings terrain_of(const json& p) {
  TerrainSettings t;
  read_param(p, "dem", t.dem);
  read_param(p, "texture", t.texture);
  read_param(p, "decimation", t.decimation);
  read_param(p, "position_bits", t.bits.position);
  read_param(p, "texcoord_bits", t.bits.texcoord);
  read_param(p, "normal_bits", t.bits.normal);
  if (p.contains("max_mib")) t.max_bytes = p.at("max_mib").get<int64_t>() << 20;
  read_param(p, "force", t.force);
  read_param(p, "draco", t.draco);
  read_param(p, "stretch", t.stretch);
  return t;
}

// The params of format panorama as `maquette render panorama`'s options (framework/cli
// cmd_render.cpp).
PanoramaJob panorama_of(const json& p) {
  PanoramaJob job;
  read_param(p, "dem", job.dem);
  read_param(p, "texture", job.texture);
  read_param(p, "stretch", job.stretch);
  read_param(p, "land_cover", job.land_cover);
  if (p.contains("smooth_land_cover") && !p.contains("land_cover"))
    throw Error("params.smooth_land_cover is given without params.land_cover: it smooths nothing");
  read_param(p, "smooth_land_cover", job.smooth_land_cover);
  const auto camera = p.at("camera").get<std::vector<double>>();
  job.camera.eye = {camera[0], camera[1], camera[2]};
  read_param(p, "above_ground", job.above_ground);
  read_param(p, "heading", job.camera.heading);
  read_param(p, "pitch", job.camera.pitch);
  if (p.contains("look_at")) {
    const auto at = p.at("look_at").get<std::vector<double>>();
    job.look_at = GeodeticPoint{at[0], at[1], at[2]};
  }
  read_param(p, "fov", job.camera.fov);
  if (p.contains("size")) {
    job.camera.width = p.at("size")[0].get<int>();
    job.camera.height = p.at("size")[1].get<int>();
  }
  read_param(p, "exaggeration", job.exaggeration);
  read_param(p, "sample_pixels", job.sample_pixels);
  if (p.contains("bend_start") && !p.contains("bend_radius"))
    throw Error("params.bend_start is given without params.bend_radius: it bends nothing");
  read_param(p, "bend_radius", job.bend.radius);
  read_param(p, "bend_start", job.bend.start);
  read_param(p, "haze_distance", job.haze_distance);
  read_param(p, "strip_rows", job.strip_rows);
  read_param(p, "shadows", job.shadows);
  read_param(p, "antialias", job.antialias);
  if (p.contains("sun")) {
    job.sun_azimuth = p.at("sun")[0].get<double>();
    job.sun_altitude = p.at("sun")[1].get<double>();
  }
  return job;
}

class ExportStep : public TaskOperator {
 public:
  const OperatorSpec& spec() const override { return spec_; }

  TaskPlan plan(const TaskContext& ctx) const override {
    const json& p = *ctx.params;
    check_format_options(p);
    if (p.at("format") == "panorama") check_panorama_job(panorama_of(p));  // before any step runs
    TaskPlan plan;
    for (const char* key : {"layer", "dem", "texture", "overlay", "land_cover"})
      if (p.contains(key)) plan.reads.emplace_back(std::string("params.") + key, p.at(key));
    if (p.contains("content"))
      for (size_t i = 0; i < p.at("content").size(); ++i)
        plan.reads.emplace_back("params.content[" + std::to_string(i) + "]", p.at("content")[i]);
    return plan;
  }

  void run(const TaskContext& ctx) const override {
    const json& p = *ctx.params;
    const std::string format = p.at("format");
    const std::string out = resolve_path(ctx.base_dir, p.at("out"));
    if (const auto parent = std::filesystem::path(out).parent_path(); !parent.empty())
      std::filesystem::create_directories(parent);
    if (format == "gtiff") {
      GtiffJob job{ctx.store_path, out, region_of(p), {}};
      read_param(p, "layer", job.spec.layer);
      if (p.contains("level")) job.spec.level = p.at("level").get<int>();
      read_param(p, "crs", job.spec.crs);
      if (p.contains("resolution")) job.spec.resolution = p.at("resolution").get<double>();
      if (p.contains("max_mib")) job.spec.max_bytes = p.at("max_mib").get<int64_t>() << 20;
      read_param(p, "force", job.spec.force);
      run_export(std::move(job));
    } else if (format == "png") {
      PngJob job;
      job.store = ctx.store_path;
      job.out = out;
      job.region = region_of(p);
      read_param(p, "layer", job.layer);
      read_param(p, "ramp", job.ramp);
      read_param(p, "range", job.range);
      read_param(p, "bands", job.bands);
      read_param(p, "hillshade", job.hillshade);
      read_param(p, "max_size", job.max_size);
      read_param(p, "projection", job.projection);
      read_param(p, "legend", job.legend);
      read_param(p, "overlay", job.overlay);
      run_export(job);
    } else if (format == "geojson" || format == "gpkg") {
      FeaturesJob job{ctx.store_path, p.at("layer"), out, region_of(p),
                      format == "gpkg" ? FeatureFormat::GeoPackage : FeatureFormat::GeoJson};
      run_export(job);
    } else if (format == "tiles3d") {
      Tiles3dJob job{ctx.store_path, out, "", region_of(p), {}};
      read_param(p, "levels", job.levels);
      job.spec.terrain = terrain_of(p);
      read_param(p, "content", job.spec.content);
      run_export(std::move(job));
    } else if (format == "panorama") {
      const auto store = Store::open(ctx.store_path, Store::Mode::ReadOnly);
      render_panorama_files(*store, default_grid(), panorama_of(p), out);
    } else {
      MeshJob job{ctx.store_path, out, {}, terrain_of(p), {}};
      read_param(p, "cells", job.cells);
      read_param(p, "content", job.content);
      (format == "glb" ? run_glb_export : run_drc_export)(job);
    }
  }

 private:
  OperatorSpec spec_ = export_spec();
};

}  // namespace

std::unique_ptr<Operator> make_export_step() { return std::make_unique<ExportStep>(); }

}  // namespace maquette::cli
