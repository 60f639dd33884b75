#include "geotiff/export_geotiff.h"

#include <cmath>
#include <filesystem>

#include "core/error.h"
#include "core/lonlat_bounds.h"
#include "core/output_file.h"
#include "gdal/gdal_env.h"
#include "geotiff/band_metadata.h"
#include "geotiff/export_crs.h"
#include "geotiff/gdal_util.h"
#include "geotiff/plane_geotiff.h"
#include "geotiff/warp.h"

namespace maquette {
namespace {

namespace fs = std::filesystem;

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
  if (!ct || !ct->Transform(2, x, y)) gdal_error("cannot transform the region centre to --crs");
  return std::hypot(x[1] - x[0], y[1] - y[0]);
}

// The output's uncompressed size: the plane raster's pixels, scaled by the pixel area ratio when
// resampled to another resolution; throws above the limit unless forced.
void check_size(const GeoTiffExport& spec, const LayerInfo& layer, const PlaneExtent& extent,
                double pixel_ratio) {
  const double pixels = double(extent.width) * double(extent.height) * pixel_ratio * pixel_ratio;
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

  const PlaneExtent extent = plane_extent(grid, cells, layer.tile_size, spec.region.bbox);

  OutputFile result(out, {".aux.xml"});
  if (crs.rhealpix) {
    check_size(spec, layer, extent, 1.0);
    write_plane_geotiff(store, grid, layer, cells, level, extent, spec.region.bbox,
                        result.temp_path());
  } else {
    // A scratch file, removed by the OutputFile that is never committed.
    const OutputFile plane((fs::temp_directory_path() / "maquette-export.tif").string(),
                           {".aux.xml"});
    WarpSpec warp{&crs.srs, 0, layer.semantics == Semantics::Categorical, spec.region.bbox};
    const double natural = default_resolution(grid, layer, level, cells[cells.size() / 2], crs.srs);
    warp.resolution = spec.resolution.value_or(natural);
    check_size(spec, layer, extent, natural / warp.resolution);
    // GDAL finds the extent from the source's edges, which miss the poles at the centres of the
    // polar squares: give it the cells' bounds in a geographic CRS.
    if (!warp.bbox_lonlat && crs.srs.IsGeographic()) {
      const LonLatBounds b = lonlat_bounds(grid, cells);
      warp.bbox_lonlat = {b.west, b.south, b.east, b.north};
    }
    write_plane_geotiff(store, grid, layer, cells, level, extent, spec.region.bbox,
                        plane.temp_path());
    GdalErrorTrap trap;
    warp_geotiff(plane.temp_path(), result.temp_path(), warp);
    DatasetPtr ds(GDALDataset::Open(result.temp_path().c_str(), GDAL_OF_RASTER | GDAL_OF_UPDATE));
    if (!ds) gdal_error("cannot reopen " + result.temp_path());
    describe_bands(*ds, layer, level);
    ds.reset();
    trap.check("cannot write " + out);
  }
  result.commit();
}

}  // namespace maquette
