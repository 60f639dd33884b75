// Raster ingest: GDAL-readable sources in any CRS, mosaicked and resampled into tiles of a store
// layer on the grid. `maquette ingest --as dem|imagery|climate|landcover|raster`. See README.md.
#pragma once

#include <array>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/geojson.h"
#include "gdal/raster_source.h"
#include "gdal/resample.h"
#include "store/store.h"

namespace maquette {

struct RasterIngestOptions {
  std::string layer;
  std::string as = "raster";                  // dem | imagery | climate | landcover | raster
  std::vector<int> bands;                     // 1-based, in channel order; empty: all
  std::optional<int> level;                   // default: from the finest source's ground pixel
  std::optional<std::array<double, 4>> bbox;  // W S E N (W > E crosses the antimeridian)
  std::string region;                         // GeoJSON file
  std::string src_crs;                        // for sources without a CRS
  std::string vertical_datum;                 // dem: egm96 | egm2008 | ellipsoid | a CRS; "": auto
  std::optional<Resampling> resampling;       // default: by semantics and scale
  int tile_size = 256;
  std::string classes;  // --classes: inline JSON or a file
  int threads = 0;      // 0: all cores
  bool resume = false;
  bool force = false;  // write even beyond the size limits
  bool quiet = false;
};

// Everything decided before the store is touched.
struct RasterIngestPlan {
  std::vector<RasterSource> sources;
  LayerInfo layer;
  Resampling resampling = Resampling::Bilinear;
  double source_pixel_m = 0;   // finest ground pixel of the sources
  double target_pixel_m = 0;   // the level's mean pixel side
  std::vector<CellId> cells;   // sorted
  int64_t estimate_bytes = 0;  // uncompressed tile bytes, an upper bound of the store's growth
  nlohmann::json run;          // identifies this ingest among run records (for --resume)
};

// Size limits of an ingest without --force.
inline constexpr int64_t kMaxIngestTiles = 1000000;
inline constexpr int64_t kMaxIngestBytes = int64_t(16) << 30;

// Reads and checks the sources and options and plans the ingest; writes nothing. Throws
// maquette::Error naming the file, option and value at fault, and with the estimate when the job
// is over the limits (unless force).
RasterIngestPlan plan_raster_ingest(const std::string& store_path,
                                    const std::vector<std::string>& sources,
                                    const RasterIngestOptions& options);

struct RasterIngestReport {
  int level = 0;
  int64_t cells = 0;    // cells of the plan
  int64_t written = 0;  // tiles written by this run
  int64_t empty = 0;    // cells without any valid sample (no tile)
  int64_t skipped = 0;  // done by the resumed run
  bool resumed = false;
  Resampling resampling = Resampling::Bilinear;
  double seconds = 0;
};

// Plans (see above), then creates the layer and writes its tiles, each cell in one batch with
// its run record, then the overviews.
RasterIngestReport ingest_raster(const std::string& store_path,
                                 const std::vector<std::string>& sources,
                                 const RasterIngestOptions& options);

}  // namespace maquette
