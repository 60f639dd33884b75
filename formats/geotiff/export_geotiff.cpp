#include "geotiff/export_geotiff.h"

#include <cmath>

#include "core/error.h"
#include "core/output_file.h"
#include "geotiff/export_crs.h"
#include "geotiff/gdal_util.h"
#include "geotiff/plane_geotiff.h"
#include "geotiff/warp.h"

namespace maquette {
namespace {

// The layer's ground pixel (metres, mean over the cell) in target units at the region centre:
// the distance in the target CRS that a pixel-long step north covers there.
double default_resolution(const Grid& grid, const LayerInfo& layer, int level, CellId centre_cell,
                          const OGRSpatialReference& target) {
  const double pixel_m = grid.level_info(level, layer.tile_size).pixel_m;
  const LonLat c = grid.centre(centre_cell);
  const double dlat = pixel_m / 111320.0;  // metres per degree of latitude, to 1 %
  OGRSpatialReference wgs84;
  wgs84.importFromEPSG(4326);
  wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  std::unique_ptr<OGRCoordinateTransformation> ct(
      OGRCreateCoordinateTransformation(&wgs84, &target));
  double x[2] = {c.lon, c.lon}, y[2] = {std::max(c.lat - dlat / 2, -90.0), 0};
  y[1] = y[0] + dlat;
  if (!ct || !ct->Transform(2, x, y))
    gdal_error("cannot transform the region centre to --crs " + crs_name(target));
  return std::hypot(x[1] - x[0], y[1] - y[0]);
}

// Throws, with the output's uncompressed size, when it is above the limit unless forced.
void check_size(const GeoTiffExport& spec, const LayerInfo& layer, double pixels) {
  const double bytes = pixels * layer.channels * double(dtype_size(layer.dtype));
  if (bytes <= double(spec.max_bytes) || spec.force) return;
  throw Error("the GeoTIFF would hold about " + std::to_string(int64_t(bytes / (1 << 20))) +
              " MiB before compression (" + std::to_string(int64_t(pixels)) + " pixels x " +
              std::to_string(layer.channels) + " channels x " +
              std::to_string(dtype_size(layer.dtype)) + " bytes), above the limit of " +
              std::to_string(spec.max_bytes >> 20) +
              " MiB: choose a coarser --level or --resolution, a smaller region, or pass --force");
}

}  // namespace

void export_geotiff(const Store& store, const Grid& grid, const GeoTiffExport& spec,
                    const std::string& out) {
  GdalSession gdal;
  const LayerInfo layer = store.require_layer(spec.layer);
  if (layer.kind != LayerKind::Raster)
    throw Error("layer '" + layer.name + "' is not a raster layer");
  const ExportCrs crs = parse_export_crs(spec.crs);
  const int level = spec.level.value_or(layer.level);
  if (level < 0 || level > layer.level)
    throw Error("--level " + std::to_string(level) + " must be in 0.." +
                std::to_string(layer.level) + " (the layer's level; coarser reads overviews)");
  if (spec.resolution && !(*spec.resolution > 0)) throw Error("--resolution must be positive");
  const std::vector<CellId> cells =
      cells_at_level(layer_tile_cells(store, grid, layer, spec.region), level);

  OutputFile result(out, {".aux.xml"});
  result.write([&] {
    if (crs.rhealpix) {
      const PlaneExtent extent = plane_extent(grid, cells, layer.tile_size, spec.region.bbox);
      check_size(spec, layer, double(extent.width) * double(extent.height));
      write_plane_geotiff(store, grid, layer, cells, level, extent, spec.region.bbox,
                          result.temp_path());
    } else {
      WarpSpec warp{&crs.srs, 0, layer.semantics == Semantics::Categorical, spec.region.bbox};
      warp.resolution = spec.resolution.value_or(
          default_resolution(grid, layer, level, cells[cells.size() / 2], crs.srs));
      const WarpGrid pixels = warp_grid(grid, cells, warp);
      check_size(spec, layer, double(pixels.width) * double(pixels.height));
      write_warped_geotiff(store, grid, layer, cells, level, warp, pixels, result.temp_path());
    }
  });
  result.commit();
}

}  // namespace maquette
