#include "geotiff/plane_geotiff.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <tuple>

#include "core/error.h"
#include "core/samples.h"
#include "gdal/gdal_env.h"
#include "geotiff/band_metadata.h"
#include "geotiff/export_crs.h"
#include "geotiff/gdal_util.h"
#include "image/picture_frame.h"

namespace maquette {
namespace {

constexpr int kBoxLattice = 129;  // points per side of a box projected to find its plane bounds

struct Placed {
  CellId cell;
  int64_t col = 0, row = 0;  // top-left pixel in the output
};

// Sets every sample of `raw` (the tile of a cell with plane square `sq`) whose pixel centre lies
// outside the box to `nodata`: a box is curved in the plane on the polar faces.
void mask_outside(RawTile& raw, const Grid& grid, const PlaneSquare& sq,
                  const std::array<double, 4>& bbox, double nodata) {
  const int n = raw.size;
  const double step = sq.side / n;
  visit_dtype(raw.dtype, [&]<typename T>(std::type_identity<T>) {
    const T value = cast_sample<T>(nodata);
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c) {
        const LonLat p = grid.inverse({sq.x_min + (c + 0.5) * step, sq.y_max - (r + 0.5) * step});
        if (in_bbox(bbox, p)) continue;
        for (int k = 0; k < raw.channels; ++k)
          std::memcpy(raw.bytes.data() + ((size_t(r) * n + c) * raw.channels + k) * sizeof(T),
                      &value, sizeof(T));
      }
  });
}

}  // namespace

PlaneExtent plane_extent(const Grid& grid, const std::vector<CellId>& cells, int tile_size,
                         const std::optional<std::array<double, 4>>& bbox) {
  PlaneExtent e;
  e.pixel = grid.plane_square(cells.front()).side / tile_size;
  double x_min = INFINITY, y_max = -INFINITY, x_max = -INFINITY, y_min = INFINITY;
  for (CellId c : cells) {
    const PlaneSquare s = grid.plane_square(c);
    x_min = std::min(x_min, s.x_min);
    y_max = std::max(y_max, s.y_max);
    x_max = std::max(x_max, s.x_min + s.side);
    y_min = std::min(y_min, s.y_max - s.side);
  }
  e.x_min = x_min, e.y_max = y_max;
  // Cell corners are multiples of the pixel in the plane, so offsets are exact integers.
  int64_t c0 = 0, r0 = 0, c1 = std::llround((x_max - x_min) / e.pixel),
          r1 = std::llround((y_max - y_min) / e.pixel);
  if (bbox) {
    // The box's points (a lattice, so that parts on several faces all count) in the plane.
    double bx0 = INFINITY, by1 = -INFINITY, bx1 = -INFINITY, by0 = INFINITY;
    std::vector<LonLat> points = bbox_points(*bbox, kBoxLattice);
    if ((*bbox)[3] >= 90) points.push_back({0, 90});
    if ((*bbox)[1] <= -90) points.push_back({0, -90});
    for (const LonLat& ll : points) {
      const PlanePoint p = grid.forward({std::remainder(ll.lon, 360.0), ll.lat});
      bx0 = std::min(bx0, p.x), bx1 = std::max(bx1, p.x);
      by0 = std::min(by0, p.y), by1 = std::max(by1, p.y);
    }
    // Whole pixels, outwards; 1e-6 pixel of slack keeps exact edges from adding a pixel.
    c0 = std::max(c0, int64_t(std::floor((bx0 - x_min) / e.pixel + 1e-6)));
    c1 = std::min(c1, int64_t(std::ceil((bx1 - x_min) / e.pixel - 1e-6)));
    r0 = std::max(r0, int64_t(std::floor((y_max - by1) / e.pixel + 1e-6)));
    r1 = std::min(r1, int64_t(std::ceil((y_max - by0) / e.pixel - 1e-6)));
  }
  e.x_min += double(c0) * e.pixel;
  e.y_max -= double(r0) * e.pixel;
  e.width = std::max<int64_t>(c1 - c0, 1);
  e.height = std::max<int64_t>(r1 - r0, 1);
  return e;
}

void write_plane_geotiff(const Store& store, const Grid& grid, const LayerInfo& layer,
                         const std::vector<CellId>& cells, int level, const PlaneExtent& extent,
                         const std::optional<std::array<double, 4>>& bbox,
                         const std::string& path) {
  const int n = layer.tile_size;
  const int64_t width = extent.width, height = extent.height;
  const double pixel = extent.pixel, x_min = extent.x_min, y_max = extent.y_max;
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

  GdalErrorTrap trap;  // GDAL may lose blocks on a full disk and only say so while closing
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
    // The part of the tile inside the extent.
    const int64_t c0 = std::max<int64_t>(p.col, 0), r0 = std::max<int64_t>(p.row, 0);
    const int64_t c1 = std::min<int64_t>(p.col + n, width),
                  r1 = std::min<int64_t>(p.row + n, height);
    if (c1 <= c0 || r1 <= r0) continue;
    if (const auto nodata = export_nodata(layer); bbox && nodata)
      mask_outside(*raw, grid, grid.plane_square(p.cell), *bbox, *nodata);
    const GSpacing pixel_bytes = GSpacing(sample) * layer.channels;
    std::byte* first =
        raw->bytes.data() + (r0 - p.row) * n * pixel_bytes + (c0 - p.col) * pixel_bytes;
    if (ds->RasterIO(GF_Write, int(c0), int(r0), int(c1 - c0), int(r1 - r0), first, int(c1 - c0),
                     int(r1 - r0), type, layer.channels, nullptr, pixel_bytes, pixel_bytes * n,
                     sample, nullptr) != CE_None)
      gdal_error("cannot write " + path);
    ++written;
  }
  if (written == 0)
    throw Error("layer '" + layer.name + "' has no " + (base ? "tiles" : "overview tiles") +
                " at level " + std::to_string(level) + " in the region");
  ds.reset();  // flushes the last blocks
  trap.check("cannot write " + path);
}

}  // namespace maquette
