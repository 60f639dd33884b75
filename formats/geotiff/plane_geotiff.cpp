#include "geotiff/plane_geotiff.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <tuple>

#include "core/error.h"
#include "geotiff/band_metadata.h"
#include "geotiff/export_crs.h"
#include "geotiff/gdal_util.h"

namespace maquette {
namespace {

struct Placed {
  CellId cell;
  int64_t col = 0, row = 0;  // top-left pixel in the output
};

}  // namespace

void write_plane_geotiff(const Store& store, const Grid& grid, const LayerInfo& layer,
                         const std::vector<CellId>& cells, int level, const std::string& path) {
  const int n = layer.tile_size;
  const double pixel = grid.plane_square(cells.front()).side / n;
  double x_min = INFINITY, y_max = -INFINITY, x_max = -INFINITY, y_min = INFINITY;
  for (CellId c : cells) {
    const PlaneSquare s = grid.plane_square(c);
    x_min = std::min(x_min, s.x_min);
    y_max = std::max(y_max, s.y_max);
    x_max = std::max(x_max, s.x_min + s.side);
    y_min = std::min(y_min, s.y_max - s.side);
  }
  // Cell corners are multiples of the pixel in the plane, so offsets are exact integers.
  const int64_t width = std::llround((x_max - x_min) / pixel);
  const int64_t height = std::llround((y_max - y_min) / pixel);
  if (width > INT_MAX || height > INT_MAX)
    throw Error("the region is too large for one GeoTIFF (" + std::to_string(width) + " x " +
                std::to_string(height) + " pixels): choose a coarser --level or a smaller region");

  std::vector<Placed> placed;
  for (CellId c : cells) {
    const PlaneSquare s = grid.plane_square(c);
    placed.push_back(
        {c, std::llround((s.x_min - x_min) / pixel), std::llround((y_max - s.y_max) / pixel)});
  }
  // Row-major order keeps partly written 256 x 256 blocks few (GDAL's cache holds them).
  std::sort(placed.begin(), placed.end(), [](const Placed& a, const Placed& b) {
    return std::tie(a.row, a.col) < std::tie(b.row, b.col);
  });

  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("GTiff");
  const GDALDataType type = gdal_type(layer.dtype);
  DatasetPtr ds(driver->Create(
      path.c_str(), int(width), int(height), layer.channels, type,
      geotiff_creation_options(layer.dtype == DType::F32 || layer.dtype == DType::F64).List()));
  if (!ds) gdal_error("cannot create " + path);
  double transform[6] = {x_min, pixel, 0, y_max, 0, -pixel};
  OGRSpatialReference srs;
  srs.importFromProj4(kRHealpixProj);
  if (ds->SetGeoTransform(transform) != CE_None || ds->SetSpatialRef(&srs) != CE_None)
    gdal_error("cannot georeference " + path);
  ds->SetMetadataItem("MAQUETTE_CRS", kRHealpixProj);  // in the TIFF itself, unlike the WKT
  describe_bands(*ds, layer, level);

  const bool base = level == layer.level;
  const int sample = int(dtype_size(layer.dtype));
  int64_t written = 0;
  for (const Placed& p : placed) {
    auto raw = base ? store.get_tile(layer.name, p.cell) : store.get_overview(layer.name, p.cell);
    if (!raw) continue;
    if (raw->size != n || raw->channels != layer.channels || raw->dtype != layer.dtype)
      throw Error("tile " + p.cell.ToText() + " of layer '" + layer.name +
                  "' does not match the layer's definition");
    if (ds->RasterIO(GF_Write, int(p.col), int(p.row), n, n, raw->bytes.data(), n, n, type,
                     layer.channels, nullptr, GSpacing(sample) * layer.channels,
                     GSpacing(sample) * layer.channels * n, sample, nullptr) != CE_None)
      gdal_error("cannot write " + path);
    ++written;
  }
  if (written == 0)
    throw Error("layer '" + layer.name + "' has no " + (base ? "tiles" : "overview tiles") +
                " at level " + std::to_string(level) + " in the region");
  ds.reset();  // flushes the last blocks
  if (CPLGetLastErrorType() == CE_Failure) gdal_error("cannot write " + path);
}

}  // namespace maquette
