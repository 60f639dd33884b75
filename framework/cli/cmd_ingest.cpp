// maquette ingest STORE --layer NAME --as KIND SOURCE...: rasters through GDAL (formats/gdal),
// vector features and station tables through OGR (formats/vector), glTF models (the mesh
// plug-in).
#include <memory>

#include "cli/commands.h"
#include "cli/ingest_job.h"

namespace maquette::cli {

void add_ingest_command(CLI::App& app) {
  auto o = std::make_shared<IngestJob>();
  CLI::App* cmd = app.add_subcommand(
      "ingest",
      "Ingest sources into a store layer: rasters (any GDAL format and CRS, mosaicked and "
      "resampled onto the grid), OGR vector features, CSV station tables, glTF models (prototypes "
      "of instances)");
  cmd->add_option("STORE", o->store, "Store file (created if absent)")->required();
  cmd->add_option("SOURCE", o->sources,
                  "Input files; rasters are mosaicked in order (a later "
                  "one fills only where earlier ones have no data)")
      ->required();
  cmd->add_option("--layer", o->raster.layer, "Layer (or stations artifact) to write")->required();
  cmd->add_option("--as", o->raster.as,
                  "dem | imagery | climate | landcover | raster | features | stations | model "
                  "(one .glb or .gltf, its y up turned to z up, its lowest point moved to z = 0, "
                  "its origin kept in x and y; written again, it replaces the model)")
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
  cmd->add_option("--vertical-datum", o->raster.vertical_datum,
                  "dem: what the heights are measured from: egm96 | egm2008 | ellipsoid | a "
                  "vertical CRS (EPSG:5703); default: from the source's CRS, else egm96");
  cmd->add_option("--resampling", o->resampling,
                  "nearest | bilinear | cubic | mode | average (default: bilinear, or nearest "
                  "for landcover; average/mode when the tiles are coarser than the source)");
  cmd->add_option("--tile-size", o->raster.tile_size, "Samples per tile side (a power of two)")
      ->capture_default_str();
  cmd->add_option("--classes", o->raster.classes,
                  "Land-cover classes, inline JSON or file: {\"11\": {\"name\": \"Open water\", "
                  "\"color\": \"#466b9f\"}, ...} (default: from the source)");
  add_threads_option(cmd, o->raster.threads);
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
    o->raster.quiet = global_options().quiet;
    run_ingest(*o);
  });
}

}  // namespace maquette::cli
