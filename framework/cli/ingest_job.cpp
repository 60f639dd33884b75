#include "cli/ingest_job.h"

#include <spdlog/spdlog.h>

#include <array>

#include "content/prototypes.h"
#include "core/error.h"
#include "core/region.h"
#include "plugins/mesh_export.h"
#include "plugins/model_ingest.h"
#include "runtime/plugin.h"
#include "store/created_store.h"
#include "vector/vector_ingest.h"

namespace maquette::cli {
namespace {

void ingest_rasters(const IngestJob& job) {
  const RasterIngestOptions r = raster_options(job);
  const RasterIngestReport rep = ingest_raster(job.store, job.sources, r);
  spdlog::info(
      "layer {}: {} cells at level {}: {} tiles written, {} without data, {} already done; {} "
      "in {:.2f} s{}",
      r.layer, rep.cells, rep.level, rep.written, rep.empty, rep.skipped,
      resampling_name(rep.resampling), rep.seconds, rep.resumed ? " (resumed)" : "");
}

// Stations or features into an open store.
void ingest_vectors_into(Store& store, const IngestJob& o) {
  if (o.raster.as == "stations") {
    StationsIngestOptions s;
    s.layer = o.raster.layer;
    s.lon_column = o.lon;
    s.lat_column = o.lat;
    s.elevation_column = o.elevation;
    s.value_columns = o.values;
    const StationsIngestReport rep = ingest_stations(store, o.sources.front(), s);
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
    f.region = compact(cover_box(default_grid(), o.bbox, level, Containment::Overlap, "--bbox"));
  } else if (!o.raster.region.empty()) {
    const auto polygons = read_geojson_polygons(o.raster.region);
    check_cover_size(polygons, level, o.raster.region);
    f.region = compact(cover_geojson(default_grid(), polygons, level, Containment::Overlap));
  }
  const FeatureIngestReport rep = ingest_features(store, o.sources, f);
  spdlog::info(
      "layer {}: {} features at level {} ({} cell entries), {} invalid skipped, {} "
      "outside the region",
      f.layer, rep.features, rep.level, rep.cell_entries, rep.invalid_skipped, rep.outside_skipped);
}

void ingest_vectors(const IngestJob& o) {
  if (o.raster.as == "stations" && o.sources.size() != 1)
    throw Error("--as stations takes one CSV file, got " + std::to_string(o.sources.size()));
  if (!o.raster.vertical_datum.empty())
    throw Error("--vertical-datum is for height layers (--as dem), not --as " + o.raster.as);
  if (!o.raster.classes.empty())  // it was ignored
    throw Error("--classes is for class layers (--as landcover), not --as " + o.raster.as);
  auto store = Store::open(o.store, Store::Mode::Create);
  try {
    ingest_vectors_into(*store, o);
  } catch (...) {
    remove_if_created(std::move(store));  // a failed ingest leaves no new store
    throw;
  }
}

// One glTF model into a model layer: read and encoded (mesh plug-in) before the store is opened,
// then written, or replaced, in one transaction, so a bad file stores nothing.
void ingest_model(const IngestJob& o) {
  if (o.sources.size() != 1)
    throw Error("--as model takes one .glb or .gltf file, got " + std::to_string(o.sources.size()));
  if (o.level || !o.bbox.empty() || !o.raster.region.empty() || !o.raster.bands.empty() ||
      !o.raster.vertical_datum.empty() || !o.raster.classes.empty())
    throw Error(
        "--as model takes none of --level, --bbox, --region, --bands, --vertical-datum, "
        "--classes: a model is in its own frame");
  const std::string& file = o.sources.front();
  // Instances name their prototypes: a model called like a built-in one would be mistaken for it.
  if (o.raster.layer.starts_with(kBuiltinPrototypePrefix))
    throw Error(file + ": cannot ingest a model as layer '" + o.raster.layer +
                "': names beginning '" + std::string(kBuiltinPrototypePrefix) +
                "' are the built-in prototypes");
  Store::check_writable(o.store);
  std::string blob;
  plugin_function<decltype(maquette_mesh_model)>(kMeshPlugin, kModelIngestEntry)(file, blob);
  auto store = Store::open(o.store, Store::Mode::Create);
  try {
    Store::Batch batch(*store);
    batch.put_model(o.raster.layer, blob, {{"source", file}});
    batch.commit();
  } catch (...) {
    remove_if_created(std::move(store));  // a failed ingest leaves no new store
    throw;
  }
  const ModelStats st = store->model_stats(o.raster.layer);
  spdlog::info("model {}: {} objects, {} triangles, {} materials, {} bytes", o.raster.layer,
               st.content.objects, st.content.triangles, st.materials, st.bytes);
}

}  // namespace

bool is_raster_job(const IngestJob& job) {
  return job.raster.as != "features" && job.raster.as != "stations" && job.raster.as != "model";
}

RasterIngestOptions raster_options(const IngestJob& job) {
  RasterIngestOptions r = job.raster;
  r.level = job.level;
  if (!job.bbox.empty()) {
    check_bbox(job.bbox, "--bbox");
    r.bbox = std::array<double, 4>{job.bbox[0], job.bbox[1], job.bbox[2], job.bbox[3]};
  }
  if (!job.resampling.empty()) r.resampling = parse_resampling(job.resampling);
  return r;
}

void run_ingest(const IngestJob& job) {
  if (is_raster_job(job))
    ingest_rasters(job);
  else if (job.raster.as == "model")
    ingest_model(job);
  else
    ingest_vectors(job);
}

}  // namespace maquette::cli
