#include "geotiff/warp.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <memory>

#include "core/error.h"
#include "core/lonlat_bounds.h"
#include "gdal/gdal_env.h"
#include "geotiff/band_metadata.h"
#include "geotiff/gdal_util.h"
#include "image/layer_sampler.h"
#include "image/picture_frame.h"

namespace maquette {
namespace {

constexpr int kStripRows = 256;     // the GeoTIFF's block height: each strip writes whole blocks
constexpr int kDensifyPoints = 21;  // per edge of the box transformed to the CRS (as gdalwarp)

using TransformPtr = std::unique_ptr<OGRCoordinateTransformation>;

OGRSpatialReference lonlat_crs() {
  OGRSpatialReference wgs84;
  wgs84.importFromEPSG(4326);
  wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  return wgs84;
}

// Samples rows [row0, row0 + rows) of the output into `values` (channels interleaved, NaN where
// there is no data); returns whether any pixel has data.
class StripSampler {
 public:
  StripSampler(const Store& store, const Grid& grid, const LayerInfo& layer,
               const std::vector<CellId>& cells, int level, const WarpSpec& spec,
               const WarpGrid& target)
      : grid_(grid),
        layer_(layer),
        level_(level),
        spec_(spec),
        target_(target),
        sampler_(store, grid, layer, level,
                 spec.nearest ? LayerSampler::Read::kNearest : LayerSampler::Read::kBilinear),
        region_(cells) {
    std::sort(region_.begin(), region_.end());
    const OGRSpatialReference wgs84 = lonlat_crs();
    to_lonlat_.reset(OGRCreateCoordinateTransformation(spec.crs, &wgs84));
    if (!to_lonlat_) gdal_error("cannot transform --crs " + crs_name(*spec.crs) + " to lon/lat");
  }

  bool sample(int row0, int rows, std::vector<float>& values) {
    const int w = target_.width, nc = layer_.channels;
    values.assign(size_t(w) * size_t(rows) * size_t(nc), std::numeric_limits<float>::quiet_NaN());
    bool any = false;
    for (int r = 0; r < rows; ++r) {
      x_.resize(size_t(w)), y_.resize(size_t(w)), ok_.resize(size_t(w));
      for (int c = 0; c < w; ++c) {
        x_[size_t(c)] = target_.left + (c + 0.5) * target_.pixel;
        y_[size_t(c)] = target_.top - (row0 + r + 0.5) * target_.pixel;
      }
      to_lonlat_->Transform(size_t(w), x_.data(), y_.data(), nullptr, ok_.data());
      points_.resize(size_t(w));
      inside_.assign(size_t(w), 0);
      for (size_t c = 0; c < size_t(w); ++c) {
        const LonLat p{std::remainder(x_[c], 360.0), y_[c]};
        inside_[c] = ok_[c] && std::abs(p.lat) <= 90 && (!spec_.bbox || in_bbox(*spec_.bbox, p));
        points_[c] = inside_[c] ? p : LonLat{0, 0};  // any valid point; not sampled
      }
      cells_.resize(size_t(w));
      grid_.cells_from_points(points_, level_, cells_);
      for (size_t c = 0; c < size_t(w); ++c) {
        if (!inside_[c] || !std::binary_search(region_.begin(), region_.end(), cells_[c])) continue;
        any |= sampler_.sample(points_[c], cells_[c],
                               values.data() + (size_t(r) * size_t(w) + c) * size_t(nc));
      }
    }
    sampler_.forget_unused();  // keeps the tiles the next strip meets first
    return any;
  }

 private:
  const Grid& grid_;
  const LayerInfo& layer_;
  int level_;
  const WarpSpec& spec_;
  WarpGrid target_;
  LayerSampler sampler_;
  std::vector<CellId> region_;  // sorted
  TransformPtr to_lonlat_;
  std::vector<double> x_, y_;
  std::vector<int> ok_;
  std::vector<LonLat> points_;
  std::vector<char> inside_;
  std::vector<CellId> cells_;
};

// Samples reach the GeoTIFF through float32 (LayerSampler), which holds integers up to 2^24
// exactly: a uint32 or int32 layer holding a larger value in the region is refused rather than
// exported with another value.
void check_float32_exact(const Store& store, const LayerInfo& layer,
                         const std::vector<CellId>& cells, int level) {
  if (layer.dtype != DType::U32 && layer.dtype != DType::I32) return;
  constexpr double kExact = 1 << 24;
  const double* nodata = layer.nodata ? &*layer.nodata : nullptr;
  for (CellId cell : cells) {
    const auto raw = level == layer.level ? store.get_tile(layer.name, cell)
                                          : store.get_overview(layer.name, cell);
    if (!raw) continue;
    const Tile<double> tile = to_tile<double>(*raw, nodata);  // a range-for would not keep it
    for (double v : tile.data())
      if (std::abs(v) > kExact)
        throw Error("layer '" + layer.name + "' holds " + std::string(dtype_name(layer.dtype)) +
                    " value " + std::to_string(int64_t(v)) + " in cell " + cell.ToText() +
                    ", beyond 2^24: an export to an EPSG CRS samples through float32 and would " +
                    "change it; export it with --crs rhealpix (exact)");
  }
}

}  // namespace

WarpGrid warp_grid(const Grid& grid, const std::vector<CellId>& cells, const WarpSpec& spec) {
  const OGRSpatialReference& target = *spec.crs;
  std::array<double, 4> box;
  if (spec.bbox) {
    box = *spec.bbox;
  } else {
    const LonLatBounds b = lonlat_bounds(grid, cells);
    box = {b.west, b.south, b.east > 180 ? b.east - 360 : b.east, b.north};
  }
  const OGRSpatialReference wgs84 = lonlat_crs();
  const TransformPtr to_target(OGRCreateCoordinateTransformation(&wgs84, &target));
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  if (!to_target || !to_target->TransformBounds(box[0], box[1], box[2], box[3], &x0, &y0, &x1, &y1,
                                                kDensifyPoints))
    gdal_error("cannot transform the region's bounds to --crs " + crs_name(target));
  if (target.IsGeographic() && x0 > x1) x1 += 360;  // across the antimeridian: east beyond 180
  WarpGrid t{x0, y1, spec.resolution, 0, 0};
  const double width = (x1 - x0 + spec.resolution / 2) / spec.resolution,
               height = (y1 - y0 + spec.resolution / 2) / spec.resolution;
  if (!(width < INT_MAX && height < INT_MAX))
    throw Error("the region is too large for one GeoTIFF at --resolution " +
                std::to_string(spec.resolution) + ": choose a coarser one or a smaller region");
  t.width = std::max(1, int(width));
  t.height = std::max(1, int(height));
  return t;
}

void write_warped_geotiff(const Store& store, const Grid& grid, const LayerInfo& layer,
                          const std::vector<CellId>& cells, int level, const WarpSpec& spec,
                          const WarpGrid& target, const std::string& path) {
  check_float32_exact(store, layer, cells, level);
  GdalErrorTrap trap;  // GDAL may lose blocks on a full disk and only say so while closing
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("GTiff");
  const GDALDataType type = gdal_type(layer.dtype);
  DatasetPtr ds(driver->Create(
      path.c_str(), target.width, target.height, layer.channels, type,
      geotiff_creation_options(layer.dtype == DType::F32 || layer.dtype == DType::F64).List()));
  if (!ds) gdal_error("cannot create " + path);
  double transform[6] = {target.left, target.pixel, 0, target.top, 0, -target.pixel};
  if (ds->SetGeoTransform(transform) != CE_None || ds->SetSpatialRef(spec.crs) != CE_None)
    gdal_error("cannot georeference " + path);
  describe_bands(*ds, layer, level);

  // Missing samples are written as the nodata value, or 0 (an integer layer without one).
  const float fill = float(export_nodata(layer).value_or(0));
  StripSampler strips(store, grid, layer, cells, level, spec, target);
  std::vector<float> values;
  bool any = false;
  for (int row0 = 0; row0 < target.height; row0 += kStripRows) {
    const int rows = std::min(kStripRows, target.height - row0);
    if (!strips.sample(row0, rows, values)) continue;  // left sparse: read as nodata
    any = true;
    for (float& v : values)
      if (std::isnan(v)) v = fill;
    const GSpacing pixel_bytes = GSpacing(sizeof(float)) * layer.channels;
    if (ds->RasterIO(GF_Write, 0, row0, target.width, rows, values.data(), target.width, rows,
                     GDT_Float32, layer.channels, nullptr, pixel_bytes, pixel_bytes * target.width,
                     sizeof(float), nullptr) != CE_None)
      gdal_error("cannot write " + path);
  }
  if (!any)
    throw Error("layer '" + layer.name + "' has no " +
                (level == layer.level ? "tiles" : "overview tiles") + " at level " +
                std::to_string(level) + " in the region");
  ds.reset();  // flushes the last blocks
  trap.check("cannot write " + path);
}

}  // namespace maquette
