// One ingest, as `maquette ingest` options or an `ingest` pipeline step's params describe it:
// rasters through GDAL (formats/gdal), vector features and station tables through OGR
// (formats/vector), glTF models through the mesh plug-in (plugins/model_ingest.h).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "gdal/raster_ingest.h"

namespace maquette::cli {

struct IngestJob {
  std::string store;
  std::vector<std::string> sources;
  std::vector<double> bbox;  // W S E N, or empty
  std::optional<int> level;
  std::string resampling;      // "" for the default
  RasterIngestOptions raster;  // layer, as, bands, region, src_crs, tile_size, classes, ...
  std::string lon = "lon", lat = "lat", elevation = "elev_m";  // stations: columns
  std::vector<std::string> values;                             // stations: value columns
};

// features and stations go through OGR, models through the mesh plug-in, the other kinds through
// GDAL.
bool is_raster_job(const IngestJob& job);
// The raster ingest's options (bbox, level and resampling checked and converted).
RasterIngestOptions raster_options(const IngestJob& job);
// Ingests, then logs what was written. Throws maquette::Error.
void run_ingest(const IngestJob& job);

}  // namespace maquette::cli
