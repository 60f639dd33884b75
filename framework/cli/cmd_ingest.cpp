// maquette ingest STORE --layer NAME --as KIND SOURCE...: rasters through GDAL (formats/gdal),
// vector features and station tables through OGR (formats/vector).
#include <spdlog/spdlog.h>

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "core/error.h"
#include "core/region.h"
#include "gdal/raster_ingest.h"
#include "vector/vector_ingest.h"

namespace maquette::cli {
namespace {

struct IngestCommandOptions {
  std::string store;
  std::vector<std::string> sources;
  std::vector<double> bbox;
  std::optional<int> level;
  std::string resampling;
  RasterIngestOptions raster;
  std::string lon = "lon", lat = "lat", elevation = "elev_m";
  std::vector<std::string> values;
};

void ingest_rasters(IngestCommandOptions& o) {
  RasterIngestOptions& r = o.raster;
  r.quiet = global_options().quiet;
  r.level = o.level;
  if (!o.bbox.empty()) r.bbox = std::array<double, 4>{o.bbox[0], o.bbox[1], o.bbox[2], o.bbox[3]};
  if (!o.resampling.empty()) r.resampling = parse_resampling(o.resampling);
  const RasterIngestReport rep = ingest_raster(o.store, o.sources, r);
  spdlog::info(
      "layer {}: {} cells at level {}: {} tiles written, {} without data, {} already done; {} "
      "in {:.2f} s{}",
      r.layer, rep.cells, rep.level, rep.written, rep.empty, rep.skipped,
      resampling_name(rep.resampling), rep.seconds, rep.resumed ? " (resumed)" : "");
}

void ingest_vectors(const IngestCommandOptions& o) {
  if (o.raster.as == "stations" && o.sources.size() != 1)
    throw Error("--as stations takes one CSV file, got " + std::to_string(o.sources.size()));
  auto store = Store::open(o.store, Store::Mode::Create);
  if (o.raster.as == "stations") {
    StationsIngestOptions s;
    s.layer = o.raster.layer;
    s.lon_column = o.lon;
    s.lat_column = o.lat;
    s.elevation_column = o.elevation;
    s.value_columns = o.values;
    const StationsIngestReport rep = ingest_stations(*store, o.sources.front(), s);
    spdlog::info("artifact {}: {} stations, {} value columns", s.layer, rep.stations,
                 rep.value_columns.size());
    return;
  }
  FeatureIngestOptions f;
  f.layer = o.raster.layer;
  f.level = o.level;
  f.src_crs = o.raster.src_crs;
  f.resume = o.raster.resume;
  // The region as compact cells (at --level, or 8: ~20 km cells, to keep big regions cheap).
  const int level = o.level.value_or(8);
  if (!o.bbox.empty()) {
    check_bbox(o.bbox, "--bbox");
    f.region = compact(default_grid().cover_bbox(o.bbox[0], o.bbox[1], o.bbox[2], o.bbox[3], level,
                                                 Containment::Overlap));
  } else if (!o.raster.region.empty()) {
    f.region = compact(cover_geojson(default_grid(), read_geojson_polygons(o.raster.region), level,
                                     Containment::Overlap));
  }
  const FeatureIngestReport rep = ingest_features(*store, o.sources, f);
  spdlog::info(
      "layer {}: {} features at level {} ({} cell entries), {} invalid skipped, {} "
      "outside the region",
      f.layer, rep.features, rep.level, rep.cell_entries, rep.invalid_skipped, rep.outside_skipped);
}

}  // namespace

void add_ingest_command(CLI::App& app) {
  auto o = std::make_shared<IngestCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "ingest",
      "Ingest sources into a store layer: rasters (any GDAL format and CRS, mosaicked and "
      "resampled onto the grid), OGR vector features, CSV station tables");
  cmd->add_option("STORE", o->store, "Store file (created if absent)")->required();
  cmd->add_option("SOURCE", o->sources,
                  "Input files; rasters are mosaicked in order (a later "
                  "one fills only where earlier ones have no data)")
      ->required();
  cmd->add_option("--layer", o->raster.layer, "Layer (or stations artifact) to write")->required();
  cmd->add_option("--as", o->raster.as,
                  "dem | imagery | climate | landcover | raster | features | stations")
      ->required();
  cmd->add_option("--bands", o->raster.bands, "Bands to read, 1-based, in channel order (4,3,2)")
      ->delimiter(',');
  cmd->add_option("--level,-l", o->level,
                  "Cell level of the tiles (default: the coarsest whose pixel is not coarser "
                  "than the finest source's ground pixel)");
  auto* bbox = cmd->add_option("--bbox", o->bbox,
                               "Only this lon/lat box: W S E N (W > E crosses "
                               "the antimeridian)")
                   ->expected(4);
  cmd->add_option("--region", o->raster.region, "Only this GeoJSON (Multi)Polygon file")
      ->excludes(bbox);
  cmd->add_option("--src-crs", o->raster.src_crs,
                  "CRS of sources that have none (EPSG:4326, WKT or PROJ string)");
  cmd->add_option("--resampling", o->resampling,
                  "nearest | bilinear | cubic | mode | average (default: bilinear, or nearest "
                  "for landcover; average/mode when the tiles are coarser than the source)");
  cmd->add_option("--tile-size", o->raster.tile_size, "Samples per tile side (a power of two)")
      ->capture_default_str();
  cmd->add_option("--classes", o->raster.classes,
                  "Land-cover classes, inline JSON or file: {\"11\": {\"name\": \"Open water\", "
                  "\"color\": \"#466b9f\"}, ...} (default: from the source)");
  cmd->add_option("-t,--threads", o->raster.threads, "Worker threads (0: all cores)")
      ->capture_default_str()
      ->check(CLI::Range(0, 1024));
  cmd->add_flag("--resume", o->raster.resume,
                "Finish the latest unfinished ingest of the same sources and options");
  cmd->add_flag("--force", o->raster.force, "Write even when the job is over the size limits");
  cmd->add_option("--lon", o->lon, "stations: longitude column")->capture_default_str();
  cmd->add_option("--lat", o->lat, "stations: latitude column")->capture_default_str();
  cmd->add_option("--elevation", o->elevation, "stations: elevation column")->capture_default_str();
  cmd->add_option("--values", o->values,
                  "stations: value columns (default: every other "
                  "numeric column)")
      ->delimiter(',');
  cmd->callback([o] {
    if (o->raster.as == "features" || o->raster.as == "stations") {
      ingest_vectors(*o);
      return;
    }
    ingest_rasters(*o);
  });
}

}  // namespace maquette::cli
