// Vector and table ingest: OGR features into a `features` layer indexed by cell, and CSV station
// tables into an artifact. Called by `maquette ingest --as features|stations`.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/cell_id.h"
#include "store/store.h"

namespace maquette {

struct FeatureIngestOptions {
  std::string layer;           // the features layer to write
  std::optional<int> level;    // index level; default: chosen from the features' extent
  std::vector<CellId> region;  // keep features touching these cells; empty: all
  std::string src_crs;         // override for sources without a CRS ("EPSG:32612", WKT, PROJ)
  bool resume = false;         // finish a killed ingest of the same sources and options
  int64_t batch_size = 512;    // features per transaction (and per run record)
};

// Counts of the features this call read: on --resume, the batches the interrupted run had
// committed are skipped (not re-read into the counts) and counted in batches_resumed.
struct FeatureIngestReport {
  int64_t features = 0;         // stored
  int64_t invalid_skipped = 0;  // not transformable to lon/lat, or off the grid: reported, skipped
  int64_t outside_skipped = 0;  // outside the region
  int64_t cell_entries = 0;     // (cell, feature) index entries
  int64_t batches_resumed = 0;  // batches already committed by the interrupted run
  int level = 0;
};

// Called after each committed batch with the counts so far (progress; may throw to abort).
using FeatureIngestProgress = std::function<void(const FeatureIngestReport&)>;

// Throws maquette::Error naming the source (and feature id) for unreadable input. Every source
// is opened, its CRS checked and every geometry checked before anything is written: a feature
// without geometry, with an empty one, a coordinate that is not finite (NaN) or a geometry GEOS
// finds invalid (a self-intersecting polygon, ...) is an error naming the source, layer and
// feature id. Throws, leaving no new layer, when no feature is stored (sources without features,
// or every feature outside the region). See formats/vector/README.md.
FeatureIngestReport ingest_features(Store& store, const std::vector<std::string>& sources,
                                    const FeatureIngestOptions& options,
                                    const FeatureIngestProgress& progress = {});

struct StationsIngestOptions {
  std::string layer;  // artifact name
  std::string lon_column = "lon", lat_column = "lat", elevation_column = "elev_m";
  std::string id_column = "id", name_column = "name";  // optional: null when absent
  std::vector<std::string> value_columns;              // empty: every other numeric column
};

struct StationsIngestReport {
  int64_t stations = 0;
  std::vector<std::string> value_columns;
};

// Throws maquette::Error naming the file, line and column for a missing column or a bad value.
StationsIngestReport ingest_stations(Store& store, const std::string& csv_path,
                                     const StationsIngestOptions& options);

}  // namespace maquette
