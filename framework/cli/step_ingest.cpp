// The `ingest` pipeline step: `maquette ingest` as a task. Params mirror the command's options
// (sources relative to the pipeline file); the step's output "layer" names the layer written (for
// stations: the artifact).
#include "cli/builtin_steps.h"
#include "cli/ingest_job.h"
#include "core/error.h"
#include "core/geojson.h"
#include "runtime/task_operator.h"

namespace maquette::cli {
namespace {

using json = nlohmann::json;

OperatorSpec ingest_spec() {
  OperatorSpec s;
  s.name = "ingest";
  s.description =
      "Ingest sources into a layer, as `maquette ingest`: rasters through GDAL, OGR features, "
      "CSV station tables, glTF models";
  s.kind = OperatorKind::Task;
  OutputSpec layer;  // dtype, channels and the rest come from the sources and "as"
  layer.name = "layer";
  layer.description = "the layer written (stations: the artifact; model: the model layer)";
  s.outputs = {layer};
  s.params_schema = {
      {"type", "object"},
      {"additionalProperties", false},
      {"required", {"sources", "as"}},
      {"properties",
       {{"sources",
         array_schema("string", "input files, relative to the pipeline file, mosaicked in order")},
        {"as",
         {{"type", "string"},
          {"enum",
           {"dem", "imagery", "climate", "landcover", "raster", "features", "stations", "model"}}}},
        {"bands",
         {{"type", "array"},
          {"items", {{"type", "integer"}, {"minimum", 1}}},
          {"description", "bands to read, 1-based, in channel order"}}},
        {"level",
         {{"type", "integer"},
          {"minimum", 0},
          {"maximum", CellId::kMaxLevel},
          {"description", "default: from the finest source's ground pixel"}}},
        {"bbox",
         {{"type", "array"},
          {"items", {{"type", "number"}}},
          {"description", "only this lon/lat box: W S E N"}}},
        {"region", {{"type", "string"}, {"description", "only this GeoJSON (Multi)Polygon file"}}},
        {"src_crs", {{"type", "string"}, {"description", "CRS of sources that have none"}}},
        {"vertical_datum",
         {{"type", "string"},
          {"description", "dem: egm96 | egm2008 | ellipsoid | a vertical CRS (EPSG:5703)"}}},
        {"resampling",
         {{"type", "string"}, {"enum", {"nearest", "bilinear", "cubic", "mode", "average"}}}},
        {"tile_size", {{"type", "integer"}, {"minimum", 1}, {"maximum", 4096}}},
        {"classes",
         {{"type", "object"},
          {"description", "land-cover classes: {\"11\": {\"name\", \"color\"}, ...}"}}},
        {"force", {{"type", "boolean"}, {"description", "write even over the size limits"}}},
        {"lon", {{"type", "string"}, {"description", "stations: longitude column"}}},
        {"lat", {{"type", "string"}, {"description", "stations: latitude column"}}},
        {"elevation", {{"type", "string"}, {"description", "stations: elevation column"}}},
        {"values",
         array_schema("string", "stations: value columns (default: every other numeric one)")}}}};
  return s;
}

class IngestStep : public TaskOperator {
 public:
  const OperatorSpec& spec() const override { return spec_; }

  TaskPlan plan(const TaskContext& ctx) const override {
    const IngestJob job = job_of(ctx);
    TaskPlan plan;
    if (!is_raster_job(job)) {
      plan.written = job.raster.layer;
      return plan;
    }
    RasterIngestPlan raster = plan_raster_ingest(job.store, job.sources, raster_options(job));
    plan.layer = std::move(raster.layer);
    plan.cells = std::move(raster.cells);
    return plan;
  }

  void run(const TaskContext& ctx) const override { run_ingest(job_of(ctx)); }

 private:
  static IngestJob job_of(const TaskContext& ctx) {
    const json& p = *ctx.params;
    IngestJob job;
    job.store = ctx.store_path;
    for (const std::string& source : p.at("sources").get<std::vector<std::string>>())
      job.sources.push_back(resolve_path(ctx.base_dir, source));
    if (job.sources.empty()) throw Error("params.sources: no source file");
    job.raster.layer = ctx.outputs->at("layer");
    read_param(p, "as", job.raster.as);
    read_param(p, "bands", job.raster.bands);
    read_param(p, "bbox", job.bbox);
    if (!job.bbox.empty()) check_bbox(job.bbox, "params.bbox");
    if (p.contains("level")) job.level = p.at("level").get<int>();
    if (p.contains("region"))
      job.raster.region = resolve_path(ctx.base_dir, p.at("region").get<std::string>());
    if (!job.bbox.empty() && !job.raster.region.empty())
      throw Error("params: give at most one of \"bbox\" and \"region\"");
    read_param(p, "src_crs", job.raster.src_crs);
    read_param(p, "vertical_datum", job.raster.vertical_datum);
    read_param(p, "resampling", job.resampling);
    read_param(p, "tile_size", job.raster.tile_size);
    if (p.contains("classes")) job.raster.classes = p.at("classes").dump();
    read_param(p, "force", job.raster.force);
    read_param(p, "lon", job.lon);
    read_param(p, "lat", job.lat);
    read_param(p, "elevation", job.elevation);
    read_param(p, "values", job.values);
    job.raster.threads = ctx.threads;
    job.raster.resume = ctx.resume;
    job.raster.quiet = ctx.quiet;
    return job;
  }

  OperatorSpec spec_ = ingest_spec();
};

}  // namespace

std::unique_ptr<Operator> make_ingest_step() { return std::make_unique<IngestStep>(); }

}  // namespace maquette::cli
