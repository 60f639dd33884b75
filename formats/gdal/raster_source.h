// A raster source as the ingest sees it: what `describe_source` learns from the file once (size,
// georeferencing, CRS, selected bands, dtype, nodata, scale/offset), and `SourceReader`, which
// reads windows of it as float samples (NaN = missing).
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/tile.h"

class GDALDataset;
class OGRSpatialReference;

namespace maquette {

struct RasterSource {
  std::string path;
  int width = 0, height = 0;
  std::array<double, 6> geotransform{};  // pixel -> source CRS (GDAL convention)
  std::array<double, 6> inverse{};       // source CRS -> pixel
  std::string crs_wkt;                   // the file's CRS, or --src-crs (WKT2)
  // The same CRS as GDAL built it (the file's own or from --src-crs): transformations are
  // created from it rather than from crs_wkt, whose import has to be exported again as WKT1
  // when GDAL creates a transformation, a search of PROJ's database (~6-18 ms for WGS 84).
  std::shared_ptr<const OGRSpatialReference> crs;
  bool geographic = false;   // the CRS is geographic (degrees)
  bool wraps = false;        // geographic, north-up and 360 degrees wide: columns wrap around
  std::vector<int> bands;    // 1-based band numbers read, in output channel order
  DType dtype = DType::F32;  // of the first selected band
  std::vector<std::optional<double>> nodata;  // per selected band
  std::vector<double> scale, offset;          // per selected band (1 and 0 when unset)
  bool scaled = false;                        // some band has scale != 1 or offset != 0
  std::string unit_type;                      // of the first selected band ("" when unset)
  int64_t file_size = 0, mtime = 0;           // for resume: a changed file is another ingest
  nlohmann::json classes = nlohmann::json::object();  // class table (see class_table.h)
};

// Opens and checks a source; throws maquette::Error naming the file: not readable by GDAL
// (missing, truncated, corrupt), no georeferencing, no CRS and no `src_crs`, a band out of range,
// an unsupported data type. Empty `bands`: every band.
RasterSource describe_source(const std::string& path, const std::vector<int>& bands,
                             const std::string& src_crs);

// A window of source pixels [x0, x0 + w) x [y0, y0 + h), possibly read at a coarser resolution
// (`step` source pixels per window pixel, averaged), one float plane per selected band with
// nodata as NaN and scale/offset applied. Pixels outside the raster are NaN (columns wrap for
// wrapping sources).
struct Window {
  int64_t x0 = 0, y0 = 0;
  int w = 0, h = 0;
  int step = 1;
  std::vector<std::vector<float>> planes;

  float at(int band, int x, int y) const {
    if (x < 0 || y < 0 || x >= w || y >= h) return std::numeric_limits<float>::quiet_NaN();
    return planes[size_t(band)][size_t(y) * size_t(w) + size_t(x)];
  }
};

// Readers of the same file share one GDAL handle, and so its block cache: a compressed
// source's blocks are decompressed once for all threads, not once per thread. Reads through it
// take turns (a GDAL handle is not thread-safe).
class SourceReader {
 public:
  explicit SourceReader(const RasterSource& source);
  ~SourceReader();
  SourceReader(const SourceReader&) = delete;
  SourceReader& operator=(const SourceReader&) = delete;

  // Reads the window; `categorical` picks the mode instead of the mean when step > 1.
  void read(int64_t x0, int64_t y0, int w, int h, int step, bool categorical, Window& out);
  // Whether the source holds at least one valid sample, scanning block rows and stopping at the
  // first one.
  bool any_valid();

 private:
  void read_span(int band, int64_t x0, int64_t y0, int w, int h, int step, bool categorical,
                 float* out, int out_stride);
  struct Handle;
  // The open handle of a file, or a new one: closed when its last reader goes.
  static std::shared_ptr<Handle> shared_handle(const std::string& path);
  const RasterSource& source_;
  std::shared_ptr<Handle> handle_;
};

}  // namespace maquette
